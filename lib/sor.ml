(* Surfaces of revolution (see sor.mli). A segment is 6 floats: y0 y1 A
   B C D, the squared radius f(y) = ((A y + B) y + C) y + D for y in
   [y0, y1]. *)

type t = { seg : Float.Array.t; n : int; ybot : float; ytop : float; rbot2 : float; rtop2 : float;
           open_ : bool; rmax : float;
           slab : Float.Array.t
               (** per segment, a little wider than it: its lowest and
                   highest y, its least and greatest squared radius *) }

let[@inline] g a i = Float.Array.unsafe_get a i
let bounds t = (Vec3.make (-.t.rmax) t.ybot (-.t.rmax), Vec3.make t.rmax t.ytop t.rmax)

(* the cubic through (y0, v0) and (y1, v1) with slopes s0 and s1 there,
   in powers of y *)
let hermite y0 y1 v0 v1 s0 s1 =
  let h = y1 -. y0 in
  (* in powers of u = y - y0 *)
  let c0 = v0 and c1 = s0 in
  let c2 = ((3. *. (v1 -. v0) /. h) -. (2. *. s0) -. s1) /. h in
  let c3 = ((s0 +. s1) -. (2. *. (v1 -. v0) /. h)) /. (h *. h) in
  (* expand in y: u = y - y0 *)
  let a = c3 in
  let b = c2 -. (3. *. c3 *. y0) in
  let c = c1 -. (2. *. c2 *. y0) +. (3. *. c3 *. y0 *. y0) in
  let d = c0 -. (c1 *. y0) +. (c2 *. y0 *. y0) -. (c3 *. y0 *. y0 *. y0) in
  (a, b, c, d)

let[@inline] f a b c d y = (((a *. y) +. b) *. y +. c) *. y +. d

let make ~open_ (pts : (float * float) array) =
  let np = Array.length pts in
  if np < 4 then Error (Printf.sprintf "a sor needs at least 4 points, found %d" np)
  else if Array.exists (fun (r, _) -> r < 0.) pts then Error "a sor's radii cannot be negative"
  else if
    (* the curve's points (all but the first and last) rise; the first
       and last only steer slopes, over heights that must differ *)
    let rec rising i = i >= np - 2 || (snd pts.(i) < snd pts.(i + 1) && rising (i + 1)) in
    not (rising 1)
  then Error "a sor's heights must rise from each point to the next (the first and last points aside)"
  else if snd pts.(0) = snd pts.(2) || snd pts.(np - 3) = snd pts.(np - 1) then
    Error "a sor's first (last) point must be at another height than its third (third from last)"
  else begin
    let n = np - 3 in
    let seg = Float.Array.create (6 * n) and slab = Float.Array.create (4 * n) in
    let rmax2 = ref 0. in
    for i = 0 to n - 1 do
      let r0, ym = pts.(i) and r1, y0 = pts.(i + 1) and r2, y1 = pts.(i + 2) and r3, yp = pts.(i + 3) in
      let s0 = 2. *. r1 *. (r2 -. r0) /. (y1 -. ym) and s1 = 2. *. r2 *. (r3 -. r1) /. (yp -. y0) in
      let a, b, c, d = hermite y0 y1 (r1 *. r1) (r2 *. r2) s0 s1 in
      List.iteri (fun j v -> Float.Array.set seg ((6 * i) + j) v) [ y0; y1; a; b; c; d ];
      (* f over [y0, y1] is the cubic in s of f(y0 + s h), s in [0, 1] *)
      let h = y1 -. y0 in
      let lo, hi =
        Prism.extent (a *. h *. h *. h) (((3. *. a *. y0) +. b) *. h *. h)
          (((((3. *. a *. y0) +. (2. *. b)) *. y0) +. c) *. h) (f a b c d y0)
      in
      let pad = 1e-9 *. (1. +. Float.abs lo +. Float.abs hi) in
      let ypad = 1e-9 *. (1. +. Float.abs y0 +. Float.abs y1) in
      List.iteri (fun j v -> Float.Array.set slab ((4 * i) + j) v) [ y0 -. ypad; y1 +. ypad; lo -. pad; hi +. pad ];
      rmax2 := Float.max !rmax2 hi
    done;
    let rb, yb = pts.(1) and rt, yt = pts.(np - 2) in
    Ok { seg; n; ybot = yb; ytop = yt; rbot2 = rb *. rb; rtop2 = rt *. rt; open_; rmax = Float.sqrt !rmax2; slab }
  end

(* the segment holding height [y] (the last one for the top) *)
let segment_at t y =
  let i = ref 0 in
  while !i < t.n - 1 && y > g t.seg ((6 * !i) + 1) do incr i done;
  6 * !i

let radius2 t y =
  let o = segment_at t y in
  f (g t.seg (o + 2)) (g t.seg (o + 3)) (g t.seg (o + 4)) (g t.seg (o + 5)) y

let inside t x y z =
  y >= t.ybot && y <= t.ytop && (x *. x) +. (z *. z) < radius2 t y

type work = { e : Float.Array.t; found : Float.Array.t; sc : Poly.scratch }

let work_key = Scratch.key (fun () -> { e = Float.Array.make 4 0.; found = Float.Array.make 3 0.; sc = Poly.scratch 3 })

let[@inline] cap_hit (h : Hit.t) tmin (r : Ray.scratch) yc r2 id =
  let tc = (yc -. r.oy) /. r.dy in
  let x = r.ox +. (tc *. r.dx) and z = r.oz +. (tc *. r.dz) in
  (x *. x) +. (z *. z) <= r2 && Hit.keep h tmin tc id yc

let hit_s t (r : Ray.scratch) tmin (h : Hit.t) =
  (* [+. 0.] keeps it unboxed: joined with a boxed argument, the choice
     would box [h.floor] *)
  let tmin = let t = tmin +. 0. in if h.floor > t then h.floor else t in
  let w = Scratch.get work_key in
  let found = ref false in
  let q = r.oy and e = r.dy in
  for i = 0 to t.n - 1 do
    let o = 6 * i in
    let y0 = g t.seg o and y1 = g t.seg (o + 1) and a = g t.seg (o + 2) and b = g t.seg (o + 3)
    and c = g t.seg (o + 4) and d = g t.seg (o + 5) in
    if e <> 0. then begin
    (* most segments are out of the ray's way: not solved for *)
    let sl = t.slab and ob = 4 * i in
    if not (Prism.slab_misses r (g sl ob) (g sl (ob + 1)) (g sl (ob + 2)) (g sl (ob + 3)) tmin h.t)
    then begin
      (* in the height y along the ray: (ox e + dx (y - q))^2 + (oz e +
         dz (y - q))^2 - e^2 f(y) = 0, a cubic; t = (y - q) / e *)
      let a0 = (r.ox *. e) -. (r.dx *. q) and a1 = r.dx and b0 = (r.oz *. e) -. (r.dz *. q) and b1 = r.dz in
      let e2 = e *. e in
      let k = w.e in
      Float.Array.set k 0 ((a0 *. a0) +. (b0 *. b0) -. (e2 *. d));
      Float.Array.set k 1 ((2. *. ((a0 *. a1) +. (b0 *. b1))) -. (e2 *. c));
      Float.Array.set k 2 ((a1 *. a1) +. (b1 *. b1) -. (e2 *. b));
      Float.Array.set k 3 (-.e2 *. a);
      let deg = if a <> 0. then 3 else if Float.Array.get k 2 <> 0. then 2 else 1 in
      let m = Prism.all_roots w.sc k deg w.found y0 (y1 +. (1e-12 *. (1. +. Float.abs y1))) in
      for j = 0 to m - 1 do
        let y = Float.Array.unsafe_get w.found j in
        if Hit.keep h tmin ((y -. q) /. e) (float i) y then found := true
      done
    end
    end
    else if q >= y0 && q <= y1 then begin
      (* a level ray: the circle of the curve's radius at its height *)
      if Prism.keep_circle h tmin r (f a b c d q) (float i) q then found := true
    end
  done;
  if (not t.open_) && e <> 0. then begin
    (* the caps: discs at the first and last inner points *)
    (* ids past the segments' (a negative id is the scene's mark of its
       flat spheres) *)
    if cap_hit h tmin r t.ybot t.rbot2 (float t.n) then found := true;
    if cap_hit h tmin r t.ytop t.rtop2 (float (t.n + 1)) then found := true
  end;
  !found

let normal_into t (p : Vec3.m) (h : Hit.t) (out : Vec3.m) =
  if h.id = float t.n then Vec3.set out 0. (-1.) 0.
  else if h.id = float (t.n + 1) then Vec3.set out 0. 1. 0.
  else begin
    let o = 6 * int_of_float h.id in
    let a = g t.seg (o + 2) and b = g t.seg (o + 3) and c = g t.seg (o + 4) in
    let y = p.my in
    (* the gradient of x^2 + z^2 - f(y) *)
    let df = (((3. *. a *. y) +. (2. *. b)) *. y) +. c in
    Vec3.set out (2. *. p.mx) (-.df) (2. *. p.mz);
    if out.mx = 0. && out.my = 0. && out.mz = 0. then Vec3.set out 0. 1. 0. else Vec3.normalize_m out
  end
