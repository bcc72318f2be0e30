(* Algebraic surfaces (see algebraic.mli). *)

let max_order = 15
let terms order = (order + 1) * (order + 2) * (order + 3) / 6

type t = {
  order : int;
  coef : Float.Array.t;  (* POV-Ray's term order *)
  ex : int array;  (* the powers of x, y and z of each term *)
  ey : int array;
  ez : int array;
  below : float;  (* inside where the polynomial is below this *)
}

let make ?(inside_below = 1e-4) order coef =
  if order < 1 || order > max_order then invalid_arg "Algebraic.make: order";
  let n = terms order in
  if Array.length coef <> n then invalid_arg "Algebraic.make: number of coefficients";
  let ex = Array.make n 0 and ey = Array.make n 0 and ez = Array.make n 0 in
  let term = ref 0 in
  (* x's power falling, then y's, then z's: x^order first, the constant last *)
  for i = order downto 0 do
    for j = order - i downto 0 do
      for k = order - i - j downto 0 do
        ex.(!term) <- i;
        ey.(!term) <- j;
        ez.(!term) <- k;
        incr term
      done
    done
  done;
  { order; coef = Float.Array.init n (fun i -> coef.(i)); ex; ey; ez; below = inside_below }

let order s = s.order

let[@inline] pow x n =
  let r = ref 1. in
  for _ = 1 to n do
    r := !r *. x
  done;
  !r

let eval a x y z =
  let sum = ref 0. in
  for t = 0 to Float.Array.length a.coef - 1 do
    let c = Float.Array.unsafe_get a.coef t in
    if c <> 0. then
      sum := !sum +. (c *. pow x (Array.unsafe_get a.ex t) *. pow y (Array.unsafe_get a.ey t)
                      *. pow z (Array.unsafe_get a.ez t))
  done;
  !sum

let inside s x y z = eval s x y z < s.below

let gradient_into s x y z (out : Vec3.m) =
  let gx = ref 0. and gy = ref 0. and gz = ref 0. in
  for t = 0 to Float.Array.length s.coef - 1 do
    let c = Float.Array.unsafe_get s.coef t in
    if c <> 0. then begin
      let i = Array.unsafe_get s.ex t and j = Array.unsafe_get s.ey t and k = Array.unsafe_get s.ez t in
      let px = pow x i and py = pow y j and pz = pow z k in
      if i > 0 then gx := !gx +. (c *. float i *. pow x (i - 1) *. py *. pz);
      if j > 0 then gy := !gy +. (c *. float j *. px *. pow y (j - 1) *. pz);
      if k > 0 then gz := !gz +. (c *. float k *. px *. py *. pow z (k - 1))
    end
  done;
  Vec3.set out !gx !gy !gz

(* Per domain: the polynomial in t along a ray, and the powers of each
   coordinate along it. *)
type scratch = {
  eqn : Float.Array.t;  (* coefficient of t^m at m *)
  px : Float.Array.t;  (* (q + t n)^e, coefficient of t^m at e * (max_order + 1) + m *)
  py : Float.Array.t;
  pz : Float.Array.t;
  roots : Poly.scratch;
}

let w = max_order + 1

let scratch_key =
  Scratch.key (fun () ->
      let a () = Float.Array.make (w * w) 0. in
      { eqn = Float.Array.make w 0.; px = a (); py = a (); pz = a (); roots = Poly.scratch max_order })

(* the coefficients of (q + t n)^e for e = 0 .. order: row e from row e-1
   times (q + t n) *)
let[@inline] g a i = Float.Array.unsafe_get a i
let[@inline] set a i x = Float.Array.unsafe_set a i x

let powers p order q n =
  set p 0 1.;
  for e = 1 to order do
    let r = e * w and r0 = (e - 1) * w in
    for m = 0 to e do
      let a = if m < e then q *. g p (r0 + m) else 0. in
      let b = if m > 0 then n *. g p (r0 + m - 1) else 0. in
      set p (r + m) (a +. b)
    done
  done

(* the polynomial along the ray q + t n, into [sc.eqn] (degree [order]) *)
let along s sc qx qy qz nx ny nz =
  let order = s.order in
  powers sc.px order qx nx;
  powers sc.py order qy ny;
  powers sc.pz order qz nz;
  let eqn = sc.eqn in
  Float.Array.fill eqn 0 w 0.;
  for t = 0 to Float.Array.length s.coef - 1 do
    let c = g s.coef t in
    if c <> 0. then begin
      let i = Array.unsafe_get s.ex t and j = Array.unsafe_get s.ey t and k = Array.unsafe_get s.ez t in
      let ri = i * w and rj = j * w and rk = k * w in
      for a = 0 to i do
        let ca = c *. g sc.px (ri + a) in
        if ca <> 0. then
          for b = 0 to j do
            let cb = ca *. g sc.py (rj + b) in
            if cb <> 0. then
              for d = 0 to k do
                let m = a + b + d in
                set eqn m (g eqn m +. (cb *. g sc.pz (rk + d)))
              done
          done
      done
    end
  done

(* POV-Ray's depth tolerance: crossings this close to the ray's origin, in
   the surface's own units, are not surfaces *)
let depth_tolerance = 1e-4

let hit_s a (r : Ray.scratch) tmin (h : Hit.t) =
  (* the first crossing past the floor *)
  let tmin = if h.floor > tmin then h.floor else tmin in
  let dx = r.dx and dy = r.dy and dz = r.dz in
  let dl = Float.sqrt ((dx *. dx) +. (dy *. dy) +. (dz *. dz)) in
  let nx = dx /. dl and ny = dy /. dl and nz = dz /. dl in
  (* from the point of the line nearest the origin: small, well scaled
     coefficients *)
  let t0 = -.((r.ox *. nx) +. (r.oy *. ny) +. (r.oz *. nz)) in
  let qx = r.ox +. (t0 *. nx) and qy = r.oy +. (t0 *. ny) and qz = r.oz +. (t0 *. nz) in
  let sc = Scratch.get scratch_key in
  along a sc qx qy qz nx ny nz;
  let lo = Float.max (tmin *. dl) depth_tolerance -. t0 in
  Poly.first_root sc.roots sc.eqn a.order lo
  &&
  let t = (Poly.root sc.roots +. t0) /. dl in
  t > tmin && t < h.t
  && (h.t <- t;
      h.id <- 0.;
      true)

let first_hit a ox oy oz dx dy dz tmin =
  let r = Ray.scratch () in
  r.ox <- ox; r.oy <- oy; r.oz <- oz; r.dx <- dx; r.dy <- dy; r.dz <- dz;
  let h = Hit.create infinity in
  if hit_s a r tmin h then h.t else infinity
