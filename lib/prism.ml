(* Prisms (see prism.mli). A segment is P(s) = ((A s + B) s + C) s + D,
   s in [0, 1], in the xz plane: 8 floats, Ax Az Bx Bz Cx Cz Dx Dz. *)

type spline = Linear | Quadratic | Cubic | Bezier
type sweep = Linear_sweep | Conic_sweep

type t = {
  seg : Float.Array.t;
  box : Float.Array.t;
      (** per segment, the box of its curve in the plane, a little larger:
          x low, x high, z low, z high *)
  whole : Float.Array.t;  (** the box of all the segments' boxes, as one of [box] *)
  side : Float.Array.t;
      (** per segment, the x and z ranges (as in [box]) of its side
          between the heights: [box] itself for a linear sweep, [box]
          scaled by the heights for a conic one *)
  n : int;
  h1 : float;
  h2 : float;
  conic : bool;
  open_ : bool;
  lo : Vec3.t;
  hi : Vec3.t;
}

let bounds t = (t.lo, t.hi)
let[@inline] g a i = Float.Array.unsafe_get a i

(* POV-Ray's formulas for the segment of a spline whose points start at
   index [k] (A, B, C, D as (x, z) pairs); the caller checks the points
   it reads exist *)
let spline_segment spline (p : (float * float) array) k =
  let comb cs =
    List.fold_left (fun (x, z) (j, c) -> let px, pz = p.(k + j) in (x +. (c *. px), z +. (c *. pz))) (0., 0.) cs
  in
  match spline with
  | Linear -> ((0., 0.), (0., 0.), comb [ (0, -1.); (1, 1.) ], comb [ (0, 1.) ])
  | Quadratic -> ((0., 0.), comb [ (0, 0.5); (1, -1.); (2, 0.5) ], comb [ (0, -0.5); (2, 0.5) ], comb [ (1, 1.) ])
  | Cubic ->
      ( comb [ (0, -0.5); (1, 1.5); (2, -1.5); (3, 0.5) ],
        comb [ (0, 1.); (1, -2.5); (2, 2.); (3, -0.5) ],
        comb [ (0, -0.5); (2, 0.5) ],
        comb [ (1, 1.) ] )
  | Bezier ->
      (comb [ (3, 1.); (2, -3.); (1, 3.); (0, -1.) ], comb [ (2, 3.); (1, -6.); (0, 3.) ], comb [ (1, 3.); (0, -3.) ],
       comb [ (0, 1.) ])

(* the points a segment from index [k] reads past [k] *)
let reach_of = function Linear -> 1 | Quadratic -> 2 | Cubic | Bezier -> 3

(* POV-Ray's segments of a prism's points: a sub-curve ending where it
   returns to its first point (its control points then skipped) *)
let segments spline (p : (float * float) array) =
  let n = Array.length p in
  let segs = ref [] in
  let pt i = p.(i) in
  let first = ref (match spline with Linear | Bezier -> pt 0 | Quadratic | Cubic -> pt 1) in
  let i = ref 0 in
  let close (ax, az) (bx, bz) = Float.abs (ax -. bx) < 1e-10 && Float.abs (az -. bz) < 1e-10 in
  let err = ref None in
  while !err = None && !i < n - 1 do
    let k = !i in
    if k + reach_of spline >= n then
      err := Some "too few points: a sub-curve is not closed, or its control points are missing"
    else begin
      segs := spline_segment spline p k :: !segs;
      match spline with
      | Linear ->
          if close (pt (k + 1)) !first then begin
            i := !i + 1;
            if !i + 1 < n then first := pt (!i + 1)
          end
      | Quadratic ->
          if close (pt (k + 2)) !first then begin
            i := !i + 2;
            if !i + 2 < n then first := pt (!i + 2)
          end
      | Cubic ->
          if close (pt (k + 2)) !first then begin
            i := !i + 3;
            if !i + 2 < n then first := pt (!i + 2)
          end
      | Bezier -> i := !i + 3
    end;
    incr i
  done;
  match !err with Some e -> Error e | None -> Ok (List.rev !segs)

(* the extremes of a cubic's values over [0, 1]: the ends and the zeros
   of its derivative *)
let extent a b c d =
  let f s = (((a *. s) +. b) *. s +. c) *. s +. d in
  let lo = ref (Float.min (f 0.) (f 1.)) and hi = ref (Float.max (f 0.) (f 1.)) in
  let visit s = if s > 0. && s < 1. then (lo := Float.min !lo (f s); hi := Float.max !hi (f s)) in
  let qa = 3. *. a and qb = 2. *. b in
  (* the zeros of qa s^2 + qb s + c without cancellation: a leading
     coefficient that is rounding left over (a Catmull-Rom segment
     between equal points: 2.8e-17) made the textbook formula miss the
     extreme, and the box too small *)
  (if qa <> 0. then begin
     let disc = (qb *. qb) -. (4. *. qa *. c) in
     if disc >= 0. then begin
       let q = -0.5 *. (qb +. Float.copy_sign (Float.sqrt disc) qb) in
       if q <> 0. then begin
         visit (q /. qa);
         visit (c /. q)
       end
       else visit 0.
     end
   end
   else if qb <> 0. then visit (-.c /. qb));
  (!lo, !hi)

let make spline sweep h1 h2 ?(open_ = false) points =
  let h1, h2 = if h1 > h2 then (h2, h1) else (h1, h2) in
  let n = Array.length points in
  let least = match spline with Linear -> 3 | Quadratic -> 5 | Cubic -> 6 | Bezier -> 4 in
  if n < least then Error (Printf.sprintf "this spline needs at least %d points, found %d" least n)
  else if spline = Bezier && n mod 4 <> 0 then Error "a bezier_spline prism needs four points a segment"
  else
    match segments spline points with
    | Error e -> Error e
    | Ok segs ->
        let seg = Float.Array.create (8 * List.length segs) in
        let box = Float.Array.create (4 * List.length segs) in
        let xl = ref infinity and xh = ref neg_infinity and zl = ref infinity and zh = ref neg_infinity in
        List.iteri
          (fun i ((ax, az), (bx, bz), (cx, cz), (dx, dz)) ->
            List.iteri (fun k v -> Float.Array.set seg ((8 * i) + k) v) [ ax; az; bx; bz; cx; cz; dx; dz ];
            let a, b = extent ax bx cx dx and c, d = extent az bz cz dz in
            (* widened by far more than the rounding of the extremes *)
            let pad l h = 1e-9 *. (1. +. Float.abs l +. Float.abs h) in
            List.iteri
              (fun k v -> Float.Array.set box ((4 * i) + k) v)
              [ a -. pad a b; b +. pad a b; c -. pad c d; d +. pad c d ];
            xl := Float.min !xl a;
            xh := Float.max !xh b;
            zl := Float.min !zl c;
            zh := Float.max !zh d)
          segs;
        let whole = Float.Array.init 4 (fun k ->
          let pick a b = if k land 1 = 0 then Float.min a b else Float.max a b in
          let v = ref (g box k) in
          for i = 1 to List.length segs - 1 do v := pick !v (g box ((4 * i) + k)) done;
          !v)
        in
        let conic = sweep = Conic_sweep in
        let side =
          if not conic then box
          else
            Float.Array.init (Float.Array.length box) (fun k ->
                (* the ends of a range scaled by heights h1 to h2, a little
                   wider still: a conic hit's point is found through a
                   division (see [hit_s]) *)
                let l = g box (k land lnot 1) and h = g box (k lor 1) in
                let a = Float.min (Float.min (l *. h1) (l *. h2)) (Float.min (h *. h1) (h *. h2))
                and b = Float.max (Float.max (l *. h1) (l *. h2)) (Float.max (h *. h1) (h *. h2)) in
                let pad = 1e-6 *. (1. +. Float.abs a +. Float.abs b) in
                if k land 1 = 0 then a -. pad else b +. pad)
        in
        let lo, hi =
          if conic then
            let ends l h k1 k2 = (Float.min (Float.min (l *. k1) (l *. k2)) (Float.min (h *. k1) (h *. k2)),
                                  Float.max (Float.max (l *. k1) (l *. k2)) (Float.max (h *. k1) (h *. k2))) in
            let x0, x1 = ends !xl !xh h1 h2 and z0, z1 = ends !zl !zh h1 h2 in
            (Vec3.make x0 h1 z0, Vec3.make x1 h2 z1)
          else (Vec3.make !xl h1 !zl, Vec3.make !xh h2 !zh)
        in
        Ok { seg; box; whole; side; n = List.length segs; h1; h2; conic; open_; lo; hi }

(* {2 Roots in [0, 1]} *)

type work = { found : Float.Array.t; uv : Float.Array.t }

let work_key =
  Scratch.key (fun () ->
      { found = Float.Array.make 3 0.; uv = Float.Array.make 2 0. })

let step_key = Scratch.key (fun () -> Float.Array.make 2 0.)

(* Where the search goes on after the root in [w]'s first float: past it
   and past the sign changes rounding makes around it (the search from a
   root's own value may find it again; roots nearer than that are the
   same root to the arithmetic), and at least 1e-12 on from where it
   started, held in [w]'s second float. How far a root [r] found in
   floating point may lie from the computed polynomial's own: the
   rounding error of evaluating it there (Horner's, 2 deg eps
   sum |e_i| |r|^i) over its slope, at most 1e-6 (1 + |r|) (a double
   root's slope is about 0). Out of line, floats passed in [w] (they
   would be boxed): [all_roots] stays small enough for lathes' and sors'
   inside tests to inline it. *)
let[@inline never] step_past e deg (w : Float.Array.t) =
  let r = Float.Array.unsafe_get w 0 in
  let a = ref 0. and d = ref 0. and ar = Float.abs r in
  for i = deg downto 1 do
    a := (!a *. ar) +. Float.abs (Float.Array.unsafe_get e i);
    d := (!d *. r) +. (float_of_int i *. Float.Array.unsafe_get e i)
  done;
  let a = (!a *. ar) +. Float.abs (Float.Array.unsafe_get e 0) in
  let bound = 1e-6 *. (1. +. ar) and err = 2. *. float_of_int deg *. epsilon_float *. a in
  let u = if err >= bound *. Float.abs !d then bound else err /. Float.abs !d in
  Float.Array.unsafe_set w 1
    (Float.max
       (Float.max (r +. (1e-12 *. (1. +. Float.abs r))) (r +. (4. *. u)))
       (Float.Array.unsafe_get w 1 +. 1e-12))

(* the roots of a polynomial of degree [deg] (coefficients in [e],
   constant first) in [lo, hi), in order, into [found]; their number *)
let all_roots sc e deg (found : Float.Array.t) lo hi =
  let n = ref 0 and w = Scratch.get step_key in
  Float.Array.unsafe_set w 1 (lo -. 1e-12);
  while !n < deg && Poly.first_root_in sc e deg (Float.Array.unsafe_get w 1) hi do
    let r = Poly.root sc in
    if r >= lo then begin
      Float.Array.unsafe_set found !n r;
      incr n
    end;
    Float.Array.unsafe_set w 0 r;
    step_past e deg w
  done;
  !n

(* the roots of c3 s^3 + c2 s^2 + c1 s + c0 in [lo, hi) into [w.found],
   as [all_roots] finds them *)
let[@inline] roots w c3 c2 c1 c0 lo hi = Poly.cubic_roots_in w.found c3 c2 c1 c0 lo hi

(* Whether the line kx x + kz z + k0 = 0 of the plane misses segment
   [i]'s box: the function has one strict sign over the box, so over the
   curve inside it, and the segment's cubic has no root. Saves solving
   the cubic for most segments (a linear function is extreme at the
   box's corners). *)
let[@inline] misses t i kx kz k0 =
  let b = t.box and o = 4 * i in
  let x1 = kx *. g b o and x2 = kx *. g b (o + 1) and z1 = kz *. g b (o + 2) and z2 = kz *. g b (o + 3) in
  (* comparisons, not [Float.min]: that one calls C (for the sign of a
     zero, which cannot change the sums' signs here) *)
  let xl = if x1 < x2 then x1 else x2 and xh = if x1 < x2 then x2 else x1 in
  let zl = if z1 < z2 then z1 else z2 and zh = if z1 < z2 then z2 else z1 in
  xl +. zl +. k0 > 0. || xh +. zh +. k0 < 0.

(* Whether the ray's stretch from t0 to t1, seen from above, stays clear
   of segment [i]'s side box (x and z): with [misses], which tests the
   line, a segment against a box (the box's axes and the line's normal
   are the axes that can part them). A stretch end that is nan (an
   infinite t along a zero component) compares false and rejects
   nothing the other end does not. *)
let[@inline] stretch_misses t i (r : Ray.scratch) t0 t1 =
  let b = t.side and o = 4 * i in
  let xa = r.ox +. (t0 *. r.dx) and xb = r.ox +. (t1 *. r.dx) in
  let za = r.oz +. (t0 *. r.dz) and zb = r.oz +. (t1 *. r.dz) in
  (if xa < xb then xb < g b o || xa > g b (o + 1) else xa < g b o || xb > g b (o + 1))
  || if za < zb then zb < g b (o + 2) || za > g b (o + 3) else za < g b (o + 2) || zb > g b (o + 3)

(* Whether a ray that is not level misses, within (tmin, tmax), the
   solid between heights [ylo] and [yhi] and squared distances [near2]
   and [far2] from the y axis (a lathe's or a sor's segment): over the
   stretch where the ray's height is within the segment's, its squared
   distance from the axis (a parabola in t) stays beyond [far2] or
   within [near2]. *)
let[@inline] slab_misses (r : Ray.scratch) ylo yhi near2 far2 tmin tmax =
  let ta = (ylo -. r.oy) /. r.dy and tb = (yhi -. r.oy) /. r.dy in
  (* [Floats.fmin]/[fmax], not [Float.min]/[max] (calls to C for the
     sign of a zero): no nan here (the ray is not level), and a zero's
     sign changes no comparison below *)
  let t0 = Floats.fmax tmin (Floats.fmin ta tb) and t1 = Floats.fmin tmax (Floats.fmax ta tb) in
  t0 > t1
  ||
  let qa = (r.dx *. r.dx) +. (r.dz *. r.dz) and qb = 2. *. ((r.ox *. r.dx) +. (r.oz *. r.dz))
  and qc = (r.ox *. r.ox) +. (r.oz *. r.oz) in
  (* no local function: it would keep this one from being inlined, and
     its floats would be boxed *)
  let a0 = (((qa *. t0) +. qb) *. t0) +. qc and a1 = (((qa *. t1) +. qb) *. t1) +. qc in
  let tv = if qa > 0. then -.qb /. (2. *. qa) else t0 in
  let bottom = if tv > t0 && tv < t1 then (((qa *. tv) +. qb) *. tv) +. qc else Floats.fmin a0 a1 in
  bottom > far2 || Floats.fmax a0 a1 < near2

(* crossings of the half-line from (u, v) towards +x with the curves:
   odd inside; a segment owns its start, not its end *)
let in_curve_w t (w : work) =
  let u = Float.Array.unsafe_get w.uv 0 and v = Float.Array.unsafe_get w.uv 1 in
  let count = ref 0 in
  for i = 0 to t.n - 1 do
    let b = t.box and ob = 4 * i in
    (* a segment wholly above, below or left of the point is not crossed *)
    if not (v < g b (ob + 2) || v > g b (ob + 3) || g b (ob + 1) <= u) then begin
    let o = 8 * i in
    let ax = g t.seg o and az = g t.seg (o + 1) and bx = g t.seg (o + 2) and bz = g t.seg (o + 3)
    and cx = g t.seg (o + 4) and cz = g t.seg (o + 5) and dx = g t.seg (o + 6) and dz = g t.seg (o + 7) in
    let end_z = az +. bz +. cz +. dz in
    let k = roots w az bz cz (dz -. v) 0. 1. in
    for j = 0 to k - 1 do
      let s = Float.Array.unsafe_get w.found j in
      let x = (((ax *. s) +. bx) *. s +. cx) *. s +. dx in
      if x > u && not (end_z = v && s > 0.5) then incr count
    done
    end
  done;
  !count land 1 = 1

(* the point (u, v) handed over through the domain's work record: as
   arguments, the floats of a call that is not inlined are boxed. A point
   above, below or right of every segment's box is in none (the test
   [in_curve_w] makes of each). *)
let[@inline] in_curve t u v =
  let a = t.whole in
  not (v < g a 2 || v > g a 3 || g a 1 <= u)
  &&
  let w = Scratch.get work_key in
  Float.Array.unsafe_set w.uv 0 u;
  Float.Array.unsafe_set w.uv 1 v;
  in_curve_w t w

let[@inline] inside t x y z =
  y > t.h1 && y < t.h2
  && if t.conic then y <> 0. && in_curve t (x /. y) (z /. y) else in_curve t x z


let hit_s t (r : Ray.scratch) tmin (h : Hit.t) =
  (* [+. 0.] keeps it unboxed: joined with a boxed argument, the choice
     would box [h.floor] *)
  let tmin = let t = tmin +. 0. in if h.floor > t then h.floor else t in
  let found = ref false in
  (* the caps *)
  if (not t.open_) && r.dy <> 0. then begin
    for c = 0 to 1 do
      let hy = if c = 0 then t.h1 else t.h2 in
      let tt = (hy -. r.oy) /. r.dy in
      if tt > tmin && tt < h.t then begin
        let x = r.ox +. (tt *. r.dx) and z = r.oz +. (tt *. r.dz) in
        let inside = if t.conic then hy <> 0. && in_curve t (x /. hy) (z /. hy) else in_curve t x z in
        if inside && Hit.keep h tmin tt (float c) 0. then found := true
      end
    done
  end;
  (* the sides: a hit's height is within [h1, h2], so its t within
     [ty0, ty1], found with heights a little wider than the rounding of
     the hit's height *)
  let w = Scratch.get work_key in
  let d2 = (r.dx *. r.dx) +. (r.dz *. r.dz) in
  let e = 1e-9 *. (1. +. Float.abs t.h1 +. Float.abs t.h2 +. Float.abs r.oy) in
  let ya = (t.h1 -. e -. r.oy) /. r.dy and yb = (t.h2 +. e -. r.oy) /. r.dy in
  let level_in = r.oy >= t.h1 -. e && r.oy <= t.h2 +. e in
  let ty0 = if r.dy = 0. then (if level_in then neg_infinity else infinity) else if ya < yb then ya else yb in
  let ty1 = if r.dy = 0. then (if level_in then infinity else neg_infinity) else if ya < yb then yb else ya in
  for i = 0 to t.n - 1 do
    (* the stretch of the ray where a hit is kept: h.t falls as hits are *)
    let t0 = if tmin > ty0 then tmin else ty0 and t1 = if h.t < ty1 then h.t else ty1 in
    if t0 <= t1 && not (stretch_misses t i r t0 t1) then begin
      let o = 8 * i in
      let ax = g t.seg o and az = g t.seg (o + 1) and bx = g t.seg (o + 2) and bz = g t.seg (o + 3)
      and cx = g t.seg (o + 4) and cz = g t.seg (o + 5) and dx = g t.seg (o + 6) and dz = g t.seg (o + 7) in
      if not t.conic then begin
        if d2 > 0. && not (misses t i r.dz (-.r.dx) ((r.oz *. r.dx) -. (r.ox *. r.dz))) then begin
          (* (P(s) - o) x d = 0 in the plane *)
          let k =
            roots w ((ax *. r.dz) -. (az *. r.dx)) ((bx *. r.dz) -. (bz *. r.dx)) ((cx *. r.dz) -. (cz *. r.dx))
              (((dx -. r.ox) *. r.dz) -. ((dz -. r.oz) *. r.dx)) 0. (1. +. 1e-12)
          in
          for j = 0 to k - 1 do
            let s = Float.Array.unsafe_get w.found j in
            let px = (((ax *. s) +. bx) *. s +. cx) *. s +. dx and pz = (((az *. s) +. bz) *. s +. cz) *. s +. dz in
            let tt = (((px -. r.ox) *. r.dx) +. ((pz -. r.oz) *. r.dz)) /. d2 in
            let y = r.oy +. (tt *. r.dy) in
            if y >= t.h1 && y <= t.h2 && Hit.keep h tmin tt (float (i + 2)) s then found := true
          done
        end
      end
      else begin
        (* the point y (Px, 1, Pz) on the ray: (oz dx - ox dz) + Px (oy dz - oz dy) - Pz (oy dx - ox dy) = 0 *)
        let a = (r.oy *. r.dz) -. (r.oz *. r.dy) and b = (r.oy *. r.dx) -. (r.ox *. r.dy) in
        let k0 = (r.oz *. r.dx) -. (r.ox *. r.dz) in
        if not (misses t i a (-.b) k0) then begin
        let k =
          roots w ((ax *. a) -. (az *. b)) ((bx *. a) -. (bz *. b)) ((cx *. a) -. (cz *. b))
            ((dx *. a) -. (dz *. b) +. k0) 0. (1. +. 1e-12)
        in
        for j = 0 to k - 1 do
          let s = Float.Array.unsafe_get w.found j in
          let px = (((ax *. s) +. bx) *. s +. cx) *. s +. dx and pz = (((az *. s) +. bz) *. s +. cz) *. s +. dz in
          let den_x = r.dx -. (r.dy *. px) and den_z = r.dz -. (r.dy *. pz) in
          let tt =
            if Float.abs den_x >= Float.abs den_z then ((r.oy *. px) -. r.ox) /. den_x
            else ((r.oy *. pz) -. r.oz) /. den_z
          in
          let y = r.oy +. (tt *. r.dy) in
          if Float.is_finite tt && y >= t.h1 && y <= t.h2 && Hit.keep h tmin tt (float (i + 2)) s then found := true
        done
        end
      end
    end
  done;
  !found

let normal_into t (p : Vec3.m) (h : Hit.t) (out : Vec3.m) =
  if h.id = 0. then Vec3.set out 0. (-1.) 0.
  else if h.id = 1. then Vec3.set out 0. 1. 0.
  else begin
    (* [p] may be [out]: read before [out] is written *)
    let x = p.mx and y = p.my and z = p.mz in
    let o = 8 * (int_of_float h.id - 2) and s = h.u in
    let ax = g t.seg o and az = g t.seg (o + 1) and bx = g t.seg (o + 2) and bz = g t.seg (o + 3)
    and cx = g t.seg (o + 4) and cz = g t.seg (o + 5) and dx = g t.seg (o + 6) and dz = g t.seg (o + 7) in
    let tx = (((3. *. ax *. s) +. (2. *. bx)) *. s) +. cx and tz = (((3. *. az *. s) +. (2. *. bz)) *. s) +. cz in
    (if t.conic then begin
       let px = (((ax *. s) +. bx) *. s +. cx) *. s +. dx and pz = (((az *. s) +. bz) *. s +. cz) *. s +. dz in
       Vec3.set out tz ((pz *. tx) -. (px *. tz)) (-.tx)
     end
     else Vec3.set out tz 0. (-.tx));
    Vec3.normalize_m out;
    (* outward: a small step along it leaves the solid *)
    let e = 1e-7 *. (1. +. Float.abs x +. Float.abs y +. Float.abs z) in
    let nx = out.mx and ny = out.my and nz = out.mz in
    if inside t (x +. (e *. nx)) (y +. (e *. ny)) (z +. (e *. nz)) then Vec3.set out (-.nx) (-.ny) (-.nz)
  end

(* A level ray (dy = 0) against the circle of squared radius [rr] about
   the y axis at its height: its crossings kept in [h] with the part [id]
   and the parameter [u] (lathes and sors) *)
let[@inline] keep_circle (h : Hit.t) tmin (r : Ray.scratch) rr id u =
  let a = (r.dx *. r.dx) +. (r.dz *. r.dz) and b = 2. *. ((r.ox *. r.dx) +. (r.oz *. r.dz))
  and c = (r.ox *. r.ox) +. (r.oz *. r.oz) -. rr in
  let disc = (b *. b) -. (4. *. a *. c) in
  if a > 0. && rr >= 0. && disc >= 0. then begin
    let sq = Float.sqrt disc in
    let k1 = Hit.keep h tmin ((-.b -. sq) /. (2. *. a)) id u in
    let k2 = Hit.keep h tmin ((-.b +. sq) /. (2. *. a)) id u in
    k1 || k2
  end
  else false
