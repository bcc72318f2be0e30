type kind =
  | Point
  | Spot of { point_at : Vec3.t; radius : float; falloff : float; tightness : float }
  | Parallel of { point_at : Vec3.t }

type t = {
  position : Vec3.t;
  color : Color.t;
  kind : kind;
  fade_distance : float;
  fade_power : float;
  shadowless : bool;
}

let point position color =
  { position; color; kind = Point; fade_distance = 0.; fade_power = 0.; shadowless = false }

let direction_to l p =
  match l.kind with
  | Parallel { point_at } ->
      let d = Vec3.normalize (Vec3.sub l.position point_at) in
      (d, Vec3.dot (Vec3.sub l.position p) d)
  | Point | Spot _ ->
      let v = Vec3.sub l.position p in
      let dist = Vec3.length v in
      (Vec3.scale (1. /. dist) v, dist)

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
