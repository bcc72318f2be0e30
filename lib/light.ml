type kind =
  | Point
  | Spot of { point_at : Vec3.t; radius : float; falloff : float; tightness : float }
  | Parallel of { point_at : Vec3.t }

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
}

type t = {
  position : Vec3.t;
  color : Color.t;
  kind : kind;
  fade_distance : float;
  fade_power : float;
  shadowless : bool;
  area : area option;
}

let point position color =
  { position; color; kind = Point; fade_distance = 0.; fade_power = 0.; shadowless = false;
    area = None }

let area axis1 axis2 n1 n2 =
  { axis1; axis2; n1 = max 1 n1; n2 = max 1 n2; adaptive = 100; circular = false;
    orient = false; jitter = false; area_illumination = false }

let direction_to l p =
  match l.kind with
  | Parallel { point_at } ->
      let d = Vec3.normalize (Vec3.sub l.position point_at) in
      (d, Vec3.dot (Vec3.sub l.position p) d)
  | Point | Spot _ ->
      let v = Vec3.sub l.position p in
      let dist = Vec3.length v in
      (Vec3.scale (1. /. dist) v, dist)

(* [direction_to] without the tuple and vectors: the unit direction and
   the distance written into a caller's scratch record. *)
type dir = { mutable lx : float; mutable ly : float; mutable lz : float; mutable dist : float }

let dir () = { lx = 0.; ly = 0.; lz = 1.; dist = 0. }

let direction_into l (p : Vec3.m) o =
  match l.kind with
  | Parallel _ ->
      let d, dist = direction_to l (Vec3.of_m p) in
      o.lx <- d.x;
      o.ly <- d.y;
      o.lz <- d.z;
      o.dist <- dist
  | Point | Spot _ ->
      let vx = l.position.x -. p.mx and vy = l.position.y -. p.my and vz = l.position.z -. p.mz in
      let dist = Float.sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz)) in
      let k = 1. /. dist in
      o.lx <- k *. vx;
      o.ly <- k *. vy;
      o.lz <- k *. vz;
      o.dist <- dist

let rad a = a *. Float.pi /. 180.

let spot_factor ~axis ~radius ~falloff ~tightness to_point =
  let c = Vec3.dot axis to_point in
  if c <= 0. then 0.
  else
    let f = if tightness = 0. then 1. else Float.pow c tightness in
    let cr = Float.cos (rad radius) and cf = Float.cos (rad falloff) in
    if c >= cr then f
    else if c < cf then 0.
    else
      let u = (c -. cf) /. (cr -. cf) in
      f *. u *. u *. (3. -. (2. *. u))

let attenuation l p =
  let spot =
    match l.kind with
    | Point | Parallel _ -> 1.
    | Spot { point_at; radius; falloff; tightness } ->
        let axis = Vec3.normalize (Vec3.sub point_at l.position) in
        spot_factor ~axis ~radius ~falloff ~tightness
          (Vec3.normalize (Vec3.sub p l.position))
  in
  if l.fade_power > 0. && l.fade_distance <> 0. then
    let _, d = direction_to l p in
    spot *. 2. /. (1. +. Float.pow (d /. l.fade_distance) l.fade_power)
  else spot

(* the point made a vector only for spot lights and fading ones *)
let attenuation_m l (p : Vec3.m) =
  match l.kind with
  | (Point | Parallel _) when not (l.fade_power > 0. && l.fade_distance <> 0.) -> 1.
  | _ -> attenuation l (Vec3.of_m p)

let offset n i = if n <= 1 then 0. else (float_of_int i /. float_of_int (n - 1)) -. 0.5

(* [x, y, z] / |[x, y, z]| as [Vec3.normalize], component [k] *)
let[@inline] unit_k x y z k =
  let l = Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) in
  let c = match k with 0 -> x | 1 -> y | _ -> z in
  if l > 0. then 1. /. l *. c else c

(* The point [(u, v)] of the light's area seen from [p], into [out];
   inlined, so that [u] and [v] are not boxed. Scalars, no vectors made. *)
let[@inline] position_into l a (p : Vec3.m) u v (out : Vec3.m) =
  (* square [-0.5,0.5]^2 to the disc of diameter 1 (concentric map) *)
  let circ = a.circular && (u <> 0. || v <> 0.) in
  let x = 2. *. u and y = 2. *. v in
  let xr = Float.abs x > Float.abs y in
  let r = if xr then x else y in
  let phi = if not circ then 0. else if xr then Float.pi /. 4. *. (y /. x) else (Float.pi /. 2.) -. (Float.pi /. 4. *. (x /. y)) in
  let u = if circ then 0.5 *. r *. Float.cos phi else u and v = if circ then 0.5 *. r *. Float.sin phi else v in
  let c = l.position in
  if not a.orient then begin
    let a1 = a.axis1 and a2 = a.axis2 in
    Vec3.set out (c.x +. ((u *. a1.x) +. (v *. a2.x))) (c.y +. ((u *. a1.y) +. (v *. a2.y)))
      (c.z +. ((u *. a1.z) +. (v *. a2.z)))
  end
  else begin
    (* axes turned to be perpendicular to the direction to the point *)
    let dx0 = p.mx -. c.x and dy0 = p.my -. c.y and dz0 = p.mz -. c.z in
    let dx = unit_k dx0 dy0 dz0 0 and dy = unit_k dx0 dy0 dz0 1 and dz = unit_k dx0 dy0 dz0 2 in
    let hy = Float.abs dy < 0.9 in
    let hx = if hy then 0. else 1. and hyv = if hy then 1. else 0. and hz = 0. in
    (* e1 = normalize (helper x d), e2 = d x e1 *)
    let cx = (hyv *. dz) -. (hz *. dy) and cy = (hz *. dx) -. (hx *. dz) and cz = (hx *. dy) -. (hyv *. dx) in
    let e1x = unit_k cx cy cz 0 and e1y = unit_k cx cy cz 1 and e1z = unit_k cx cy cz 2 in
    let e2x = (dy *. e1z) -. (dz *. e1y) and e2y = (dz *. e1x) -. (dx *. e1z) and e2z = (dx *. e1y) -. (dy *. e1x) in
    let l1 = Vec3.length a.axis1 and l2 = Vec3.length a.axis2 in
    Vec3.set out
      (c.x +. ((u *. (l1 *. e1x)) +. (v *. (l2 *. e2x))))
      (c.y +. ((u *. (l1 *. e1y)) +. (v *. (l2 *. e2y))))
      (c.z +. ((u *. (l1 *. e1z)) +. (v *. (l2 *. e2z))))
  end

let position_at l a (p : Vec3.t) u v =
  let pm = Vec3.m () and out = Vec3.m () in
  Vec3.load pm p;
  position_into l a pm u v out;
  Vec3.of_m out

let sample_position l a p i j = position_at l a p (offset a.n1 i) (offset a.n2 j)

let differ (a : Color.t) (b : Color.t) =
  Float.abs (a.r -. b.r) +. Float.abs (a.g -. b.g) +. Float.abs (a.b -. b.b) > 0.1

let average_area a f =
  let cache = Array.make (a.n1 * a.n2) None in
  let get i j =
    match cache.((j * a.n1) + i) with
    | Some c -> c
    | None ->
        let c = f i j in
        cache.((j * a.n1) + i) <- Some c;
        c
  in
  let rec go u1 v1 u2 v2 level =
    let c1 = get u1 v1 and c2 = get u2 v1 and c3 = get u1 v2 and c4 = get u2 v2 in
    let corners () = Color.scale 0.25 (Color.add (Color.add c1 c2) (Color.add c3 c4)) in
    if u2 - u1 <= 1 && v2 - v1 <= 1 then corners ()
    else if level >= a.adaptive && not (differ c1 c2 || differ c3 c4 || differ c1 c3 || differ c2 c4)
    then corners ()
    else
      let ua = (u1 + u2) / 2 and va = (v1 + v2) / 2 in
      let ub = (u1 + u2 + 1) / 2 and vb = (v1 + v2 + 1) / 2 in
      let q a b c d = go a b c d (level + 1) in
      Color.scale 0.25
        (Color.add
           (Color.add (q u1 v1 ua va) (q ub v1 u2 va))
           (Color.add (q u1 vb ua v2) (q ub vb u2 v2)))
  in
  go 0 0 (a.n1 - 1) (a.n2 - 1) 0
