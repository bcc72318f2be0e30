(* Where a ray crosses the light of spotlights (see lit.mli). *)

let max_distance = 1e7

type span = { mutable lo : float; mutable hi : float }

let span () = { lo = 0.; hi = 0. }

(* The cone's inside, ahead of the apex, is convex: a ray meets it in one
   stretch at most. Along the ray, with [v] the origin seen from the apex,
   [a] the unit axis and [c] the cosine of the half-angle, the double cone
   is [f t = (k2 + t k1)^2 - c^2 |v + t d|^2 >= 0] (a quadratic) and the
   nappe ahead is [g t = k2 + t k1 >= 0] (a half-line): the stretch is
   where both hold. *)
let cone (l : Light.t) (r : Ray.scratch) out =
  match l.kind with
  | Light.Spot { point_at; falloff; _ } when falloff < 90. ->
      let p = l.position in
      let ax = point_at.x -. p.x and ay = point_at.y -. p.y and az = point_at.z -. p.z in
      let al = Float.sqrt ((ax *. ax) +. (ay *. ay) +. (az *. az)) in
      let ax = ax /. al and ay = ay /. al and az = az /. al in
      let c = Float.cos (falloff *. (Float.pi /. 180.)) in
      let c2 = c *. c in
      let vx = r.ox -. p.x and vy = r.oy -. p.y and vz = r.oz -. p.z in
      let k1 = (r.dx *. ax) +. (r.dy *. ay) +. (r.dz *. az)
      and k2 = (vx *. ax) +. (vy *. ay) +. (vz *. az)
      and k3 = (vx *. r.dx) +. (vy *. r.dy) +. (vz *. r.dz)
      and k4 = (vx *. vx) +. (vy *. vy) +. (vz *. vz) in
      let qa = (k1 *. k1) -. c2 and qb = (k1 *. k2) -. (c2 *. k3) and qc = (k2 *. k2) -. (c2 *. k4) in
      (* the half-line ahead of the apex *)
      let glo = if k1 > 0. then -.k2 /. k1 else if k1 < 0. || k2 >= 0. then neg_infinity else infinity
      and ghi = if k1 < 0. then -.k2 /. k1 else if k1 > 0. || k2 >= 0. then infinity else neg_infinity in
      let disc = (qb *. qb) -. (qa *. qc) in
      (* the part of the double cone that can be ahead: [flo, fhi] *)
      let flo, fhi =
        if Float.abs qa < 1e-12 then
          (* the ray parallel to a side of the cone: [f] is linear *)
          if qb > 0. then (-.qc /. (2. *. qb), infinity)
          else if qb < 0. then (neg_infinity, -.qc /. (2. *. qb))
          else if qc >= 0. then (neg_infinity, infinity)
          else (infinity, neg_infinity)
        else if disc <= 0. then
          (* no crossing: the line is all outside (qa < 0) or all inside
             the double cone (qa > 0, through its apex) *)
          if qa > 0. then (neg_infinity, infinity) else (infinity, neg_infinity)
        else
          let s = Float.sqrt disc in
          let u = (-.qb -. s) /. qa and w = (-.qb +. s) /. qa in
          let t1 = Float.min u w and t2 = Float.max u w in
          (* less steep than the cone: inside between the crossings;
             steeper: in one nappe before [t1], in the other after [t2],
             the one ahead where the ray goes along the axis *)
          if qa < 0. then (t1, t2) else if k1 > 0. then (t2, infinity) else (neg_infinity, t1)
      in
      let lo = Float.max flo glo and hi = Float.min fhi ghi in
      if lo < hi then begin
        out.lo <- lo;
        out.hi <- Float.min hi max_distance;
        true
      end
      else false
  | _ -> false

(* POV-Ray 3.7's interval of a cylindrical light (media.cpp,
   ComputeCylinderLightInterval), its quirks kept: where the ray's line is
   within [falloff] of the axis, from the ray's origin when the line
   comes out of the half-space behind the light (not from where it does),
   none when the ray runs exactly along the axis or leaves the lit side
   (the end it then gets lies behind the origin); with [v] the origin
   seen from the light and [a] the unit axis, the line is inside where
   [(1 - k1^2) t^2 + 2 (k3 - k1 k2) t + |v|^2 - k2^2 - falloff^2 < 0] *)
let cylinder (l : Light.t) (r : Ray.scratch) out =
  match l.kind with
  | Light.Cylinder { point_at; falloff; _ } ->
      let p = l.position in
      let ax = point_at.x -. p.x and ay = point_at.y -. p.y and az = point_at.z -. p.z in
      let ka = Vec3.inv_len ax ay az in
      let ux = ka *. ax and uy = ka *. ay and uz = ka *. az in
      let vx = r.ox -. p.x and vy = r.oy -. p.y and vz = r.oz -. p.z in
      let k1 = (r.dx *. ux) +. (r.dy *. uy) +. (r.dz *. uz) and k2 = (vx *. ux) +. (vy *. uy) +. (vz *. uz) in
      if k1 <= 0. && k2 < 0. then false
      else
        let a = 1. -. (k1 *. k1) in
        if a = 0. then false
        else
          let k3 = (vx *. r.dx) +. (vy *. r.dy) +. (vz *. r.dz) and k4 = (vx *. vx) +. (vy *. vy) +. (vz *. vz) in
          let b = k3 -. (k1 *. k2) and c = k4 -. (k2 *. k2) -. (falloff *. falloff) in
          let d = (b *. b) -. (a *. c) in
          if not (d > 1e-10) then false
          else
            let d = Float.sqrt d in
            let u = (-.b +. d) /. a and w = (-.b -. d) /. a in
            let t1 = if u <= w then u else w and t2 = if u <= w then w else u in
            let l1 = k2 +. (t1 *. k1) and l2 = k2 +. (t2 *. k1) in
            if l1 <= 0. && l2 <= 0. then false
            else begin
              out.lo <- (if l1 <= 0. then 0. else t1);
              out.hi <- (if l1 > 0. && l2 <= 0. then (max_distance -. k2) /. k1 else t2);
              true
            end
  | _ -> false

(* stretches as (lo, hi, lit) triples; per light the ends of its lit part,
   sorted apart as POV-Ray sorts them *)
type t = {
  mutable n : int;
  mutable b : Float.Array.t;
  mutable s0 : Float.Array.t;
  mutable s1 : Float.Array.t;
  mutable on0 : Float.Array.t;  (** by light: its lit part (empty: not lit) *)
  mutable on1 : Float.Array.t;
  sp : span;
}

let make () =
  let a () = Float.Array.make 1 0. in
  { n = 0; b = Float.Array.make 3 0.; s0 = a (); s1 = a (); on0 = a (); on1 = a (); sp = span () }

let lights t i x = x >= Float.Array.get t.on0 i && x <= Float.Array.get t.on1 i
let count t = t.n
let lo t i = Float.Array.get t.b (3 * i)
let hi t i = Float.Array.get t.b ((3 * i) + 1)
let is_lit t i = Float.Array.get t.b ((3 * i) + 2) > 0.

let[@inline] push t lo hi lit =
  let k = 3 * t.n in
  Float.Array.set t.b k lo;
  Float.Array.set t.b (k + 1) hi;
  Float.Array.set t.b (k + 2) (if lit then 1. else 0.);
  t.n <- t.n + 1

(* [cut] with the ray's length in [r.far] (a float passed to a function
   not inlined would be boxed) *)
let cut_far t (lights : Light.t array) (r : Ray.scratch) =
  let len = r.far in
  let nl = Array.length lights in
  if Float.Array.length t.b < 3 * ((2 * nl) + 1) then begin
    t.s0 <- Float.Array.make nl 0.;
    t.s1 <- Float.Array.make nl 0.;
    t.on0 <- Float.Array.make nl 0.;
    t.on1 <- Float.Array.make nl 0.;
    t.b <- Float.Array.make (3 * ((2 * nl) + 1)) 0.
  end;
  (* each light's lit part *)
  let m = ref 0 in
  for i = 0 to nl - 1 do
    let l = lights.(i) in
    Float.Array.set t.on0 i infinity;
    Float.Array.set t.on1 i neg_infinity;
    (* POV-Ray 3.7's list of lights for media (media.cpp,
       ComputeOneMediaLightInterval) holds point, spot and cylinder
       lights: a shadowless light is a fill light there, left out *)
    if l.media_interaction && not l.shadowless then begin
      match l.kind with
      | Light.Spot _ | Light.Cylinder _ ->
          let crossed = match l.kind with Light.Cylinder _ -> cylinder l r t.sp | _ -> cone l r t.sp in
          if crossed && t.sp.lo < len && t.sp.hi > 0.001 then begin
            (* plain comparisons: no float boxed *)
            Float.Array.set t.on0 i (if t.sp.lo > 0. then t.sp.lo else 0.);
            Float.Array.set t.on1 i t.sp.hi;
            if t.sp.hi > len then Float.Array.set t.on1 i len
          end
      | Light.Point | Light.Parallel _ ->
          Float.Array.set t.on0 i 0.;
          Float.Array.set t.on1 i len
    end;
    if Float.Array.get t.on0 i <= Float.Array.get t.on1 i then begin
      Float.Array.set t.s0 !m (Float.Array.get t.on0 i);
      Float.Array.set t.s1 !m (Float.Array.get t.on1 i);
      incr m
    end
  done;
  t.n <- 0;
  let m = !m in
  if m = 0 then push t 0. len false
  else begin
    (* POV-Ray sorts the starts and the ends each on its own: the merged
       stretches are the union of the lit parts all the same *)
    Floats.sort_prefix t.s0 m;
    Floats.sort_prefix t.s1 m;
    let s0 = Float.Array.get t.s0 0 in
    if s0 > 0. then push t 0. s0 false;
    push t s0 (Float.Array.get t.s1 0) true;
    for i = 1 to m - 1 do
      let a = Float.Array.get t.s0 i and b = Float.Array.get t.s1 i in
      let last = hi t (t.n - 1) in
      if a > last then begin
        push t last a false;
        push t a b true
      end
      else if b > last then Float.Array.set t.b ((3 * (t.n - 1)) + 1) b
    done;
    let last = hi t (t.n - 1) in
    if last < len then push t last len false
  end

let[@inline] cut t lights (r : Ray.scratch) len =
  r.far <- len;
  cut_far t lights r
