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
  (* The expansion along a ray (see [expand]): the products of a nonzero
     term's coefficient with a coefficient of each of its three powers
     along the ray, those that add to t^m at [prod_from.(m)] to
     [prod_from.(m + 1) - 1], in the order of the loops over the terms and
     the powers' coefficients: *)
  prod_from : int array;
  prod_coef : Float.Array.t;  (* the term's coefficient *)
  prod_at : int array;  (* the places of the other factors in the table of
                           powers along the ray (see [scratch]), packed
                           by [pack] *)
}

(* Rows of the tables of powers along a ray are [w] apart, the tables
   (of x, y and z) [w * w] apart in one array *)
let w = max_order + 1

(* three places in that array, each below 2^10 *)
let[@inline] pack ix iy iz = ix lor (iy lsl 10) lor (iz lsl 20)

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
  (* the products, term by term, then by the power of t they add to *)
  let prods = ref [] in
  for t = n - 1 downto 0 do
    if coef.(t) <> 0. then
      for a = ex.(t) downto 0 do
        for b = ey.(t) downto 0 do
          for d = ez.(t) downto 0 do
            prods :=
              (a + b + d, coef.(t), (ex.(t) * w) + a, (w * w) + (ey.(t) * w) + b, (2 * w * w) + (ez.(t) * w) + d)
              :: !prods
          done
        done
      done
  done;
  let prods = Array.of_list (List.stable_sort (fun (m, _, _, _, _) (m', _, _, _, _) -> compare m m') !prods) in
  let prod_from = Array.make (order + 2) (Array.length prods) in
  for p = Array.length prods - 1 downto 0 do
    let m, _, _, _, _ = prods.(p) in
    for m' = 0 to m do
      prod_from.(m') <- p
    done
  done;
  let field f = Array.map f prods in
  { order; coef = Float.Array.init n (fun i -> coef.(i)); ex; ey; ez; below = inside_below; prod_from;
    prod_coef = Float.Array.init (Array.length prods) (fun p -> let _, c, _, _, _ = prods.(p) in c);
    prod_at = field (fun (_, _, x, y, z) -> pack x y z) }

let order s = s.order

let quadric s =
  if s.order <> 2 then None
  else begin
    (* a x^2 + b y^2 + c z^2 + d x + e y + f z + g, no mixed terms *)
    let q = Array.make 7 0. and ok = ref true in
    for i = 0 to Float.Array.length s.coef - 1 do
      let k = Float.Array.get s.coef i in
      match (s.ex.(i), s.ey.(i), s.ez.(i)) with
      | 2, 0, 0 -> q.(0) <- k
      | 0, 2, 0 -> q.(1) <- k
      | 0, 0, 2 -> q.(2) <- k
      | 1, 0, 0 -> q.(3) <- k
      | 0, 1, 0 -> q.(4) <- k
      | 0, 0, 1 -> q.(5) <- k
      | 0, 0, 0 -> q.(6) <- k -. s.below
      | _ -> if k <> 0. then ok := false
    done;
    if !ok then Some q else None
  end

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
  pow : Float.Array.t;  (* (q + t n)^e, coefficient of t^m at e * w + m, for
                           x, then y at w * w, then z at 2 w * w *)
  roots : Poly.scratch;
}

let scratch_key =
  Scratch.key (fun () ->
      { eqn = Float.Array.make w 0.; pow = Float.Array.make (3 * w * w) 0.; roots = Poly.scratch max_order })

let[@inline] g a i = Float.Array.unsafe_get a i
let[@inline] set a i x = Float.Array.unsafe_set a i x

(* The coefficients of (q + t n)^e for e = 0 .. order: row e from row e-1
   times (q + t n), its ends adding a zero as the sum in its middle would
   (which turns a -0 into a +0). The first four rows written out: they
   are all most shapes need, and a loop over their few entries costs
   more in overhead than in arithmetic. *)
let powers p o order q n =
  set p o 1.;
  let a0 = (q *. 1.) +. 0. and a1 = 0. +. (n *. 1.) in
  set p (o + w) a0;
  set p (o + w + 1) a1;
  if order >= 2 then begin
    let b0 = (q *. a0) +. 0. and b1 = (q *. a1) +. (n *. a0) and b2 = 0. +. (n *. a1) in
    set p (o + 2 * w) b0;
    set p (o + (2 * w) + 1) b1;
    set p (o + (2 * w) + 2) b2;
    if order >= 3 then begin
      let c0 = (q *. b0) +. 0. and c1 = (q *. b1) +. (n *. b0) and c2 = (q *. b2) +. (n *. b1)
      and c3 = 0. +. (n *. b2) in
      set p (o + 3 * w) c0;
      set p (o + (3 * w) + 1) c1;
      set p (o + (3 * w) + 2) c2;
      set p (o + (3 * w) + 3) c3;
      if order >= 4 then begin
        set p (o + 4 * w) ((q *. c0) +. 0.);
        set p (o + (4 * w) + 1) ((q *. c1) +. (n *. c0));
        set p (o + (4 * w) + 2) ((q *. c2) +. (n *. c1));
        set p (o + (4 * w) + 3) ((q *. c3) +. (n *. c2));
        set p (o + (4 * w) + 4) (0. +. (n *. c3))
      end
    end
  end;
  for e = 5 to order do
    let r = e * w and r0 = (e - 1) * w in
    set p (o + r) ((q *. g p (o + r0)) +. 0.);
    for m = 1 to e - 1 do
      set p (o + r + m) ((q *. g p (o + r0 + m)) +. (n *. g p (o + r0 + m - 1)))
    done;
    set p (o + r + e) (0. +. (n *. g p (o + r0 + e - 1)))
  done

(* The polynomial along the ray q + t n, into [sc.eqn] (degree [order]):
   the sum over the terms c x^i y^j z^k of c times the product of the
   expansions of (qx + t nx)^i, (qy + t ny)^j and (qz + t nz)^k. Each
   power of t sums its products in the order of loops over the terms and
   their powers' coefficients, so to the bit as those loops did, but from
   the list the shape keeps and in a register (the loops cost twice as
   much, in their overhead and their tests for zeros).

   Those loops skipped the products that are zero (a power along the ray
   with a zero coefficient); adding them changes no sum: a sum starts at
   +0 and, rounded to nearest, no sum of a +0 with anything but a -0 is a
   -0, so adding a zero of either sign leaves it the same (the powers are
   finite: no zero times an infinity makes a nan). *)
let expand s sc qx qy qz nx ny nz =
  let order = s.order in
  let pow = sc.pow and eqn = sc.eqn in
  powers pow 0 order qx nx;
  powers pow (w * w) order qy ny;
  powers pow (2 * w * w) order qz nz;
  let from = s.prod_from and pc = s.prod_coef and at = s.prod_at in
  for m = 0 to order do
    let acc = ref 0. in
    for p = Array.unsafe_get from m to Array.unsafe_get from (m + 1) - 1 do
      let a = Array.unsafe_get at p in
      acc := !acc +. (g pc p *. g pow (a land 1023) *. g pow ((a lsr 10) land 1023) *. g pow (a lsr 20))
    done;
    set eqn m !acc
  done

(* POV-Ray's depth tolerance: crossings this close to the ray's origin, in
   the surface's own units, are not surfaces *)
let depth_tolerance = 1e-4

let hit_s a (r : Ray.scratch) tmin (h : Hit.t) =
  (* the first crossing past the floor *)
  (* [+. 0.] keeps it unboxed: joined with a boxed argument, the choice
     would box [h.floor] *)
  let tmin = let t = tmin +. 0. in if h.floor > t then h.floor else t in
  let dx = r.dx and dy = r.dy and dz = r.dz in
  let dl = Float.sqrt ((dx *. dx) +. (dy *. dy) +. (dz *. dz)) in
  let nx = dx /. dl and ny = dy /. dl and nz = dz /. dl in
  (* from the point of the line nearest the origin: small, well scaled
     coefficients *)
  let t0 = -.((r.ox *. nx) +. (r.oy *. ny) +. (r.oz *. nz)) in
  let qx = r.ox +. (t0 *. nx) and qy = r.oy +. (t0 *. ny) and qz = r.oz +. (t0 *. nz) in
  let sc = Scratch.get scratch_key in
  expand a sc qx qy qz nx ny nz;
  (* [Float.max], which calls C for the sign of a zero (none here: the
     tolerance is positive), and keeps a nan *)
  let lo = tmin *. dl in
  let lo = (if lo > depth_tolerance || lo <> lo then lo else depth_tolerance) -. t0 in
  (* roots past the query's upper bound are not wanted: the search stops
     there (a clipped surface's bound is its box's far side), the roots
     it finds the same whatever the bound *)
  let stop = (h.t *. dl) -. t0 in
  Poly.first_root_below sc.roots sc.eqn a.order lo stop
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

let along s qx qy qz nx ny nz =
  let sc = Scratch.get scratch_key in
  expand s sc qx qy qz nx ny nz;
  Float.Array.sub sc.eqn 0 (s.order + 1)
