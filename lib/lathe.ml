(* Lathes (see lathe.mli). A segment is 8 floats: Ar Ay Br By Cr Cy Dr Dy,
   radius r(s) and height y(s) = ((A s + B) s + C) s + D. *)

type t = {
  seg : Float.Array.t;
  box : Float.Array.t;
      (** per segment, a little wider than the curve: its lowest and
          highest y, the squares of its least and greatest distance from
          the axis, its greatest (signed) radius *)
  n : int;
  lo : Vec3.t;
  hi : Vec3.t;
}

let bounds t = (t.lo, t.hi)
let[@inline] g a i = Float.Array.unsafe_get a i

let make spline points =
  let np = Array.length points in
  let least = match spline with Prism.Linear -> 2 | Prism.Quadratic -> 3 | Prism.Cubic -> 4 | Prism.Bezier -> 4 in
  if np < least then Error (Printf.sprintf "this spline needs at least %d points, found %d" least np)
  else if spline = Prism.Bezier && np mod 4 <> 0 then Error "a bezier_spline lathe needs four points a segment"
  else begin
    let count = match spline with Prism.Bezier -> np / 4 | s -> np - Prism.reach_of s in
    let seg = Float.Array.create (8 * count) and box = Float.Array.create (5 * count) in
    let rmax = ref 0. and ylo = ref infinity and yhi = ref neg_infinity in
    for i = 0 to count - 1 do
      let k = match spline with Prism.Bezier -> 4 * i | _ -> i in
      let (ar, ay), (br, by), (cr, cy), (dr, dy) = Prism.spline_segment spline points k in
      List.iteri (fun j v -> Float.Array.set seg ((8 * i) + j) v) [ ar; ay; br; by; cr; cy; dr; dy ];
      let r0, r1 = Prism.extent ar br cr dr and y0, y1 = Prism.extent ay by cy dy in
      (* widened by far more than the rounding of the extremes *)
      let ypad = 1e-9 *. (1. +. Float.abs y0 +. Float.abs y1) and rpad = 1e-9 *. (1. +. Float.abs r0 +. Float.abs r1) in
      let far = Float.max (Float.abs r0) (Float.abs r1) +. rpad in
      let near = if r0 <= 0. && r1 >= 0. then 0. else Float.max 0. (Float.min (Float.abs r0) (Float.abs r1) -. rpad) in
      List.iteri
        (fun j v -> Float.Array.set box ((5 * i) + j) v)
        [ y0 -. ypad; y1 +. ypad; near *. near; far *. far; r1 +. rpad ];
      rmax := Float.max !rmax (Float.max (Float.abs r0) (Float.abs r1));
      ylo := Float.min !ylo y0;
      yhi := Float.max !yhi y1
    done;
    Ok { seg; box; n = count; lo = Vec3.make (-. !rmax) !ylo (-. !rmax); hi = Vec3.make !rmax !yhi !rmax }
  end

type work = { e : Float.Array.t; found : Float.Array.t; sc : Poly.scratch }

let work_key = Scratch.key (fun () -> { e = Float.Array.make 7 0.; found = Float.Array.make 6 0.; sc = Poly.scratch 6 })

(* crossings of the curve by the half-line of radii beyond [rho] at
   height [y]: odd inside; a segment owns its start, not its end *)
(* inlined (into the normal and the shape's inside test): its floats
   passed to a call would be boxed *)
let[@inline] inside t x y z =
  let w = Scratch.get work_key in
  let rho = Float.sqrt ((x *. x) +. (z *. z)) in
  let count = ref 0 in
  for i = 0 to t.n - 1 do
    let b = t.box and ob = 5 * i in
    (* a segment wholly above or below the point, or nearer the axis, is
       not crossed *)
    if not (y < g b ob || y > g b (ob + 1) || g b (ob + 4) <= rho) then begin
    let o = 8 * i in
    let ar = g t.seg o and ay = g t.seg (o + 1) and br = g t.seg (o + 2) and by = g t.seg (o + 3)
    and cr = g t.seg (o + 4) and cy = g t.seg (o + 5) and dr = g t.seg (o + 6) and dy = g t.seg (o + 7) in
    let e = w.e in
    Float.Array.fill e 0 7 0.;
    Float.Array.set e 0 (dy -. y);
    Float.Array.set e 1 cy;
    Float.Array.set e 2 by;
    Float.Array.set e 3 ay;
    let k = Prism.all_roots w.sc e 3 w.found 0. 1. in
    let end_y = ay +. by +. cy +. dy in
    for j = 0 to k - 1 do
      let s = Float.Array.unsafe_get w.found j in
      let r = (((ar *. s) +. br) *. s +. cr) *. s +. dr in
      if r > rho && not (end_y = y && s > 0.5) then incr count
    done
    end
  done;
  !count land 1 = 1


(* Whether a ray that is not level misses segment [i] within (tmin,
   tmax) (see {!Prism.slab_misses}): saves solving the degree-6 equation
   for most segments *)
let[@inline] misses t i (r : Ray.scratch) tmin tmax =
  let b = t.box and ob = 5 * i in
  Prism.slab_misses r (g b ob) (g b (ob + 1)) (g b (ob + 2)) (g b (ob + 3)) tmin tmax

let hit_s t (r : Ray.scratch) tmin (h : Hit.t) =
  (* [+. 0.] keeps it unboxed: joined with a boxed argument, the choice
     would box [h.floor] *)
  let tmin = let t = tmin +. 0. in if h.floor > t then h.floor else t in
  let w = Scratch.get work_key in
  let found = ref false in
  for i = 0 to t.n - 1 do
    let o = 8 * i in
    let ar = g t.seg o and ay = g t.seg (o + 1) and br = g t.seg (o + 2) and by = g t.seg (o + 3)
    and cr = g t.seg (o + 4) and cy = g t.seg (o + 5) and dr = g t.seg (o + 6) and dy = g t.seg (o + 7) in
    let e = w.e in
    if r.dy <> 0. then begin
    if not (misses t i r tmin h.t) then begin
      (* with u(s) = y(s) - oy and t = u / dy: (ox dy + dx u)^2 + (oz dy
         + dz u)^2 - dy^2 r(s)^2 = 0, of degree 6 *)
      let u0 = dy -. r.oy and u1 = cy and u2 = by and u3 = ay in
      let x0 = (r.ox *. r.dy) +. (r.dx *. u0) and x1 = r.dx *. u1 and x2 = r.dx *. u2 and x3 = r.dx *. u3 in
      let z0 = (r.oz *. r.dy) +. (r.dz *. u0) and z1 = r.dz *. u1 and z2 = r.dz *. u2 and z3 = r.dz *. u3 in
      let q = r.dy *. r.dy in
      (* the squares' coefficients, written out: X^2 + Z^2 - q R^2 *)
      Float.Array.set e 0 ((x0 *. x0) +. (z0 *. z0) -. (q *. dr *. dr));
      Float.Array.set e 1 (2. *. ((x0 *. x1) +. (z0 *. z1) -. (q *. dr *. cr)));
      Float.Array.set e 2
        ((x1 *. x1) +. (2. *. x0 *. x2) +. (z1 *. z1) +. (2. *. z0 *. z2) -. (q *. ((cr *. cr) +. (2. *. dr *. br))));
      Float.Array.set e 3
        (2. *. ((x0 *. x3) +. (x1 *. x2) +. (z0 *. z3) +. (z1 *. z2) -. (q *. ((dr *. ar) +. (cr *. br)))));
      Float.Array.set e 4
        ((x2 *. x2) +. (2. *. x1 *. x3) +. (z2 *. z2) +. (2. *. z1 *. z3) -. (q *. ((br *. br) +. (2. *. cr *. ar))));
      Float.Array.set e 5 (2. *. ((x2 *. x3) +. (z2 *. z3) -. (q *. br *. ar)));
      Float.Array.set e 6 ((x3 *. x3) +. (z3 *. z3) -. (q *. ar *. ar));
      let k = Prism.all_roots w.sc e 6 w.found 0. (1. +. 1e-12) in
      for j = 0 to k - 1 do
        let s = Float.Array.unsafe_get w.found j in
        let u = (((ay *. s) +. by) *. s +. cy) *. s +. dy -. r.oy in
        if Hit.keep h tmin (u /. r.dy) (float i) s then found := true
      done
    end
    end
    else begin
      (* a level ray: the heights where the curve is at the ray's, then
         the circle of that radius *)
      Float.Array.fill e 0 7 0.;
      Float.Array.set e 0 (dy -. r.oy);
      Float.Array.set e 1 cy;
      Float.Array.set e 2 by;
      Float.Array.set e 3 ay;
      let k = Prism.all_roots w.sc e 3 w.found 0. (1. +. 1e-12) in
      for j = 0 to k - 1 do
        let s = Float.Array.unsafe_get w.found j in
        let rho = (((ar *. s) +. br) *. s +. cr) *. s +. dr in
        if Prism.keep_circle h tmin r (rho *. rho) (float i) s then found := true
      done
    end
  done;
  !found

let normal_into t (p : Vec3.m) (h : Hit.t) (out : Vec3.m) =
  let x = p.mx and y = p.my and z = p.mz in
  let o = 8 * int_of_float h.id and s = h.u in
  let ar = g t.seg o and ay = g t.seg (o + 1) and br = g t.seg (o + 2) and by = g t.seg (o + 3)
  and cr = g t.seg (o + 4) and cy = g t.seg (o + 5) in
  let dr = (((3. *. ar *. s) +. (2. *. br)) *. s) +. cr and dy = (((3. *. ay *. s) +. (2. *. by)) *. s) +. cy in
  let rho = Float.sqrt ((x *. x) +. (z *. z)) in
  (if rho > 0. then Vec3.set out (dy *. x /. rho) (-.dr) (dy *. z /. rho) else Vec3.set out 0. (-.dr) 0.);
  if out.mx = 0. && out.my = 0. && out.mz = 0. then Vec3.set out 0. 1. 0. else Vec3.normalize_m out;
  (* outward: a small step along it leaves the solid *)
  let e = 1e-7 *. (1. +. Float.abs x +. Float.abs y +. Float.abs z) in
  let nx = out.mx and ny = out.my and nz = out.mz in
  if inside t (x +. (e *. nx)) (y +. (e *. ny)) (z +. (e *. nz)) then Vec3.set out (-.nx) (-.ny) (-.nz)
