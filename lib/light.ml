type kind =
  | Point
  | Spot of {
      point_at : Vec3.t;
      radius : float;
      falloff : float;
      tightness : float;
      cos_radius : float;
      cos_falloff : float;
    }
  | Parallel of { point_at : Vec3.t }
  | Cylinder of { point_at : Vec3.t; radius : float; falloff : float; tightness : float }

type area = {
  axis1 : Vec3.t;
  axis2 : Vec3.t;
  n1 : int;
  n2 : int;
  adaptive : int;
  circular : bool;
  orient : bool;
  jitter : bool;
  area_illumination : bool;
  offsets1 : Float.Array.t;
  offsets2 : Float.Array.t;
}

type t = {
  position : Vec3.t;
  color : Color.t;
  kind : kind;
  fade_distance : float;
  fade_power : float;
  shadowless : bool;
  area : area option;
  media_interaction : bool;
  media_attenuation : bool;
  projected_through : Object.t option;
  photons : Photon.flags;
}

let point position color =
  { position; color; kind = Point; fade_distance = 0.; fade_power = 0.; shadowless = false;
    area = None; media_interaction = true; media_attenuation = false; projected_through = None;
    photons = Photon.none }

let offset n i = if n <= 1 then 0. else (float_of_int i /. float_of_int (n - 1)) -. 0.5

let area axis1 axis2 n1 n2 =
  let n1 = max 1 n1 and n2 = max 1 n2 in
  { axis1; axis2; n1; n2; adaptive = 100; circular = false;
    orient = false; jitter = false; area_illumination = false;
    offsets1 = Float.Array.init n1 (offset n1); offsets2 = Float.Array.init n2 (offset n2) }

(* The unit direction to the light and its distance, written into a
   caller's scratch record: no tuple, no vector. *)
type dir = { mutable lx : float; mutable ly : float; mutable lz : float; mutable dist : float }

let dir () = { lx = 0.; ly = 0.; lz = 1.; dist = 0. }

(* The light as if it stood at (cx, cy, cz), seen from [p], in scalars
   (inlined: nothing boxed): [direction_to]'s distance, ... A cylindrical
   light's rays are parallel, as a parallel light's (POV-Ray 3.7,
   trace.cpp: the distance is measured along the axis, to the plane
   through the light; for a sample of an area light, along the line from
   [point_at] to the sample) *)
let[@inline] distance_at l cx cy cz (p : Vec3.m) =
  match l.kind with
  | Parallel { point_at } | Cylinder { point_at; _ } ->
      let dx = cx -. point_at.x and dy = cy -. point_at.y and dz = cz -. point_at.z in
      let k = Vec3.inv_len dx dy dz in
      ((cx -. p.mx) *. (k *. dx)) +. ((cy -. p.my) *. (k *. dy)) +. ((cz -. p.mz) *. (k *. dz))
  | Point | Spot _ ->
      let vx = cx -. p.mx and vy = cy -. p.my and vz = cz -. p.mz in
      Float.sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz))

(* ... and its unit direction with that distance, into [o] *)
let[@inline] direction_at l cx cy cz (p : Vec3.m) o =
  let dist = distance_at l cx cy cz p in
  o.dist <- dist;
  match l.kind with
  | Parallel { point_at } | Cylinder { point_at; _ } ->
      let dx = cx -. point_at.x and dy = cy -. point_at.y and dz = cz -. point_at.z in
      let k = Vec3.inv_len dx dy dz in
      o.lx <- k *. dx;
      o.ly <- k *. dy;
      o.lz <- k *. dz
  | Point | Spot _ ->
      let k = 1. /. dist in
      o.lx <- k *. (cx -. p.mx);
      o.ly <- k *. (cy -. p.my);
      o.lz <- k *. (cz -. p.mz)

let direction_into l (p : Vec3.m) o =
  let c = l.position in
  direction_at l c.x c.y c.z p o

let direction_to l (p : Vec3.t) =
  let pm = Vec3.m () and o = dir () in
  Vec3.load pm p;
  direction_into l pm o;
  (Vec3.make o.lx o.ly o.lz, o.dist)

(* times pi/180, as POV-Ray scales by M_PI_180 *)
let rad a = a *. (Float.pi /. 180.)

let spot ~point_at ~radius ~falloff ~tightness =
  Spot { point_at; radius; falloff; tightness; cos_radius = Float.cos (rad radius); cos_falloff = Float.cos (rad falloff) }

(* a spot light's factor at the cosine [c] between its axis and the
   direction to the lit point; [cr] and [cf], the cosines of its radius
   and falloff, made with the light *)
let[@inline] spot_cos c ~cr ~cf ~tightness =
  if c <= 0. then 0.
  else
    let f = if tightness = 0. then 1. else Float.pow c tightness in
    if c >= cr then f
    else if c < cf then 0.
    else
      let u = (c -. cf) /. (cr -. cf) in
      f *. u *. u *. (3. -. (2. *. u))

(* POV-Ray's cylindrical light at the distance [d] from its axis
   (lightsource.cpp, Attenuate_Light): 0 from [falloff] out, else with [x
   = 1 - d / falloff], x^tightness, times between [radius] and [falloff]
   the cubic step from 0 (at x = 0) to 1 (at x = 1 - radius / falloff) *)
let[@inline] cylinder_factor ~radius ~falloff ~tightness d =
  if not (d < falloff) then 0.
  else
    let x = 1. -. (d /. falloff) in
    let f = if tightness = 0. then 1. else Float.pow x tightness in
    if radius > 0. && d > radius then begin
      let hi = 1. -. (radius /. falloff) in
      if x < 0. then 0.
      else if x >= hi then f
      else
        let s = x /. hi in
        f *. ((3. -. (2. *. s)) *. s *. s)
    end
    else f

(* The attenuation of the light as if it stood at (cx, cy, cz), a
   spotlight's axis from (ox, oy, oz) to its point_at, at a point written
   in place, in scalars (inlined: nothing boxed) *)
let[@inline] beam_axis l ox oy oz cx cy cz (p : Vec3.m) =
    match l.kind with
    | Point | Parallel _ -> 1.
    | Cylinder { point_at; radius; falloff; tightness } ->
        (* the light's own axis, whatever the sample (as POV-Ray): the
           distance of [p] from it, nothing behind the light's plane *)
        let c = l.position in
        let ax = point_at.x -. c.x and ay = point_at.y -. c.y and az = point_at.z -. c.z in
        let ka = Vec3.inv_len ax ay az in
        let ux = ka *. ax and uy = ka *. ay and uz = ka *. az in
        let vx = p.mx -. c.x and vy = p.my -. c.y and vz = p.mz -. c.z in
        let k = (vx *. ux) +. (vy *. uy) +. (vz *. uz) in
        if k > 0. then begin
          let qx = vx -. (k *. ux) and qy = vy -. (k *. uy) and qz = vz -. (k *. uz) in
          cylinder_factor ~radius ~falloff ~tightness (Float.sqrt ((qx *. qx) +. (qy *. qy) +. (qz *. qz)))
        end
        else 0.
    | Spot { point_at; tightness; cos_radius; cos_falloff; _ } ->
        let ax = point_at.x -. ox and ay = point_at.y -. oy and az = point_at.z -. oz in
        let tx = p.mx -. cx and ty = p.my -. cy and tz = p.mz -. cz in
        let ka = Vec3.inv_len ax ay az and kt = Vec3.inv_len tx ty tz in
        let cos = ((ka *. ax) *. (kt *. tx)) +. ((ka *. ay) *. (kt *. ty)) +. ((ka *. az) *. (kt *. tz)) in
        spot_cos cos ~cr:cos_radius ~cf:cos_falloff ~tightness

let[@inline] attenuation_axis l ox oy oz cx cy cz (p : Vec3.m) =
  let spot = beam_axis l ox oy oz cx cy cz p in
  if l.fade_power > 0. && l.fade_distance <> 0. then begin
    let x = distance_at l cx cy cz p /. l.fade_distance in
    (* the usual powers multiplied out: a call of pow costs more than
       the rest of the light's attenuation *)
    let fp = l.fade_power in
    spot *. 2. /. (1. +. (if fp = 2. then x *. x else if fp = 1. then x else Float.pow x fp))
  end
  else spot

(* the spotlight's axis moved with the sample, aimed at its point_at *)
let[@inline] attenuation_at l cx cy cz (p : Vec3.m) = attenuation_axis l cx cy cz cx cy cz p

(* the spotlight's axis the light's own, whatever the sample (POV-Ray's
   Attenuate_Light for a sample's ray: the angle to the light's fixed
   direction) *)
let[@inline] attenuation_shifted l cx cy cz (p : Vec3.m) =
  let c = l.position in
  attenuation_axis l c.x c.y c.z cx cy cz p

let[@inline] attenuation_m l (p : Vec3.m) =
  let c = l.position in
  attenuation_at l c.x c.y c.z p

let beam l (p : Vec3.m) =
  let c = l.position in
  beam_axis l c.x c.y c.z c.x c.y c.z p

let attenuation l (p : Vec3.t) =
  let pm = Vec3.m () in
  Vec3.load pm p;
  attenuation_m l pm

(* The two axes of an area light's grid as seen from a point, scalars
   in a caller's record: found once per lit point, for all its samples. *)
type axes = {
  mutable ux : float;
  mutable uy : float;
  mutable uz : float;
  mutable vx : float;
  mutable vy : float;
  mutable vz : float;
}

let axes () = { ux = 1.; uy = 0.; uz = 0.; vx = 0.; vy = 0.; vz = 1. }

(* The axes of [a] seen from [p], into [o]: the light's own, or with
   orient POV-Ray's (trace.cpp, TraceAreaLightShadowRay and
   ComputeFullAreaDiffuseLight): with [d] the unit direction of the
   light ray at [p] (toward the light; a cylindrical or parallel light's
   runs from its point_at to it), the first axis along d x z (d x y when
   d is within 0.01 of +-z), the second along d x (the first); both as
   long as the first axis written (a square) *)
let[@inline] axes_into l a (p : Vec3.m) (o : axes) =
  if not a.orient then begin
    let a1 = a.axis1 and a2 = a.axis2 in
    o.ux <- a1.x;
    o.uy <- a1.y;
    o.uz <- a1.z;
    o.vx <- a2.x;
    o.vy <- a2.y;
    o.vz <- a2.z
  end
  else begin
    let c = l.position in
    let dx0 = match l.kind with Cylinder { point_at; _ } | Parallel { point_at } -> c.x -. point_at.x | _ -> c.x -. p.mx
    and dy0 = match l.kind with Cylinder { point_at; _ } | Parallel { point_at } -> c.y -. point_at.y | _ -> c.y -. p.my
    and dz0 = match l.kind with Cylinder { point_at; _ } | Parallel { point_at } -> c.z -. point_at.z | _ -> c.z -. p.mz in
    let kd = Vec3.inv_len dx0 dy0 dz0 in
    let dx = kd *. dx0 and dy = kd *. dy0 and dz = kd *. dz0 in
    let near_z = Float.abs (Float.abs dz -. 1.) < 0.01 in
    (* d x (0, 0, 1) = (dy, -dx, 0); d x (0, 1, 0) = (-dz, 0, dx) *)
    let cx = if near_z then -.dz else dy and cy = if near_z then 0. else -.dx and cz = if near_z then dx else 0. in
    let k1 = Vec3.inv_len cx cy cz in
    let e1x = k1 *. cx and e1y = k1 *. cy and e1z = k1 *. cz in
    let fx = (dy *. e1z) -. (dz *. e1y) and fy = (dz *. e1x) -. (dx *. e1z) and fz = (dx *. e1y) -. (dy *. e1x) in
    let k2 = Vec3.inv_len fx fy fz in
    let e2x = k2 *. fx and e2y = k2 *. fy and e2z = k2 *. fz in
    let l1 = Vec3.length a.axis1 in
    o.ux <- l1 *. e1x;
    o.uy <- l1 *. e1y;
    o.uz <- l1 *. e1z;
    o.vx <- l1 *. e2x;
    o.vy <- l1 *. e2y;
    o.vz <- l1 *. e2z
  end

(* The point [(u, v)] of the light's area on the axes [o], into [out];
   inlined, so that [u] and [v] are not boxed. Scalars, no vectors made. *)
let[@inline] position_on l a (o : axes) u v (out : Vec3.m) =
  (* circular: POV-Ray's square [-0.5,0.5]^2 to the disc of diameter 1
     (trace.cpp, TraceAreaLightSubsetShadowRay): the offsets moved by
     0.001 each, then along their own direction to the distance of the
     larger of them *)
  let circ = a.circular in
  let ju = u +. 0.001 and jv = v +. 0.001 in
  (* (0, 0) only for offsets of -0.001, never on the grid (mc's
     continuous samples might): left there; none of it for a square
     light *)
  let k =
    if not circ then 1.
    else
      let au = Float.abs ju and av = Float.abs jv in
      let n = Float.sqrt ((ju *. ju) +. (jv *. jv)) in
      if n > 0. then (if au > av then au else av) /. n else 1.
  in
  let u = if circ then ju *. k else u and v = if circ then jv *. k else v in
  let c = l.position in
  Vec3.set out
    (c.x +. ((u *. o.ux) +. (v *. o.vx)))
    (c.y +. ((u *. o.uy) +. (v *. o.vy)))
    (c.z +. ((u *. o.uz) +. (v *. o.vz)))

let axes_key = Scratch.key axes

(* The point [(u, v)] of the light's area seen from [p], into [out] *)
let[@inline] position_into l a (p : Vec3.m) u v (out : Vec3.m) =
  let o = Scratch.get axes_key in
  axes_into l a p o;
  position_on l a o u v out

(* grid sample ([i], [j]) on the axes [o], into [out] *)
let[@inline] sample_on l a o i j out =
  position_on l a o (Float.Array.get a.offsets1 i) (Float.Array.get a.offsets2 j) out

(* grid sample ([i], [j]) of the area seen from [p], into [out] *)
let[@inline] sample_into l a p i j out =
  position_into l a p (Float.Array.get a.offsets1 i) (Float.Array.get a.offsets2 j) out

let position_at l a (p : Vec3.t) u v =
  let pm = Vec3.m () and out = Vec3.m () in
  Vec3.load pm p;
  position_into l a pm u v out;
  Vec3.of_m out

let sample_position l a (p : Vec3.t) i j =
  let pm = Vec3.m () and out = Vec3.m () in
  Vec3.load pm p;
  sample_into l a pm i j out;
  Vec3.of_m out

(* The samples' colours met so far (3 floats each, [seen] marks them) and
   the recursion's results, 4 quadrants of 3 floats per level: per domain,
   grown as needed, so that an average allocates nothing. *)
type average = {
  mutable cols : Float.Array.t;
  mutable seen : Bytes.t;
  mutable res : Float.Array.t;
  sample : Color.acc;
  mutable busy : bool;
}

let new_average () =
  { cols = Float.Array.create 0; seen = Bytes.empty; res = Float.Array.create 0; sample = Color.acc 0.; busy = false }

let average_key = Scratch.key new_average

(* sample (i, j)'s colour, asked once: its offset in [cols] *)
let get st a ctx f i j =
  let k = (j * a.n1) + i in
  if Bytes.unsafe_get st.seen k = '\000' then begin
    let c = st.sample in
    f ctx i j c;
    Float.Array.unsafe_set st.cols (3 * k) c.ar;
    Float.Array.unsafe_set st.cols ((3 * k) + 1) c.ag;
    Float.Array.unsafe_set st.cols ((3 * k) + 2) c.ab;
    Bytes.unsafe_set st.seen k '\001'
  end;
  3 * k

(* as [differ] on two samples' colours *)
let fget = Float.Array.unsafe_get

let differ_at cols x y =
  Float.abs (fget cols x -. fget cols y)
  +. Float.abs (fget cols (x + 1) -. fget cols (y + 1))
  +. Float.abs (fget cols (x + 2) -. fget cols (y + 2))
  > 0.1

(* the average of a quadrant, into [st.res] at [slot]; its sub-quadrants'
   at the next level's four slots *)
let rec quadrant st a ctx f u1 v1 u2 v2 level slot =
  let c1 = get st a ctx f u1 v1 and c2 = get st a ctx f u2 v1 and c3 = get st a ctx f u1 v2
  and c4 = get st a ctx f u2 v2 in
  let cols = st.cols and res = st.res in
  if (u2 - u1 <= 1 && v2 - v1 <= 1)
     || level >= a.adaptive
        && not (differ_at cols c1 c2 || differ_at cols c3 c4 || differ_at cols c1 c3 || differ_at cols c2 c4)
  then
    for x = 0 to 2 do
      Float.Array.unsafe_set res (slot + x)
        (0.25 *. ((fget cols (c1 + x) +. fget cols (c2 + x)) +. (fget cols (c3 + x) +. fget cols (c4 + x))))
    done
  else begin
    let ua = (u1 + u2) / 2 and va = (v1 + v2) / 2 in
    let ub = (u1 + u2 + 1) / 2 and vb = (v1 + v2 + 1) / 2 in
    let q = 12 * (level + 1) in
    quadrant st a ctx f u1 v1 ua va (level + 1) q;
    quadrant st a ctx f ub v1 u2 va (level + 1) (q + 3);
    quadrant st a ctx f u1 vb ua v2 (level + 1) (q + 6);
    quadrant st a ctx f ub vb u2 v2 (level + 1) (q + 9);
    for x = 0 to 2 do
      Float.Array.unsafe_set res (slot + x)
        (0.25 *. ((fget res (q + x) +. fget res (q + 3 + x)) +. (fget res (q + 6 + x) +. fget res (q + 9 + x))))
    done
  end

let average_area_into a ctx f (out : Color.acc) =
  let st =
    let st = Scratch.get average_key in
    if st.busy then new_average () else st
  in
  st.busy <- true;
  let n = a.n1 * a.n2 in
  if Bytes.length st.seen < n then begin
    st.seen <- Bytes.create n;
    st.cols <- Float.Array.create (3 * n)
  end;
  Bytes.fill st.seen 0 n '\000';
  (* each level halves the larger side: the recursion ends at single
     cells within log2 (max n1 n2) + 2 levels *)
  let levels = ref 2 and m = ref (Int.max a.n1 a.n2) in
  while !m > 0 do
    incr levels;
    m := !m lsr 1
  done;
  if Float.Array.length st.res < 12 * (!levels + 1) then st.res <- Float.Array.create (12 * (!levels + 1));
  match quadrant st a ctx f 0 0 (a.n1 - 1) (a.n2 - 1) 0 0 with
  | () ->
      st.busy <- false;
      Color.acc_set out (fget st.res 0) (fget st.res 1) (fget st.res 2)
  | exception e ->
      st.busy <- false;
      raise e

let average_area a f =
  let out = Color.acc 0. in
  average_area_into a f
    (fun f i j (o : Color.acc) ->
      let c : Color.t = f i j in
      Color.acc_set o c.r c.g c.b)
    out;
  Color.of_acc out
