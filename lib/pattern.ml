type wave = Ramp | Triangle | Sine | Scallop | Cubic | Poly of float

type kind =
  | Checker
  | Hexagon
  | Brick of { size : Vec3.t; mortar : float }
  | Gradient of Vec3.t
  | Radial
  | Onion
  | Wood
  | Marble
  | Leopard
  | Bozo
  | Spotted
  | Bumps
  | Dents
  | Granite
  | Agate of float
  | Ripples
  | Waves
  | Wrinkles
  | Crackle

type turbulence = { amount : Vec3.t; octaves : int; omega : float; lambda : float }

type t = {
  kind : kind;
  turbulence : turbulence option;
  frequency : float;
  phase : float;
  wave : wave option;
}

let make kind = { kind; turbulence = None; frequency = 1.; phase = 0.; wave = None }

let gradient v =
  let l = Vec3.length v in
  Gradient (if l = 0. then Vec3.unit_x else Vec3.scale (1. /. l) v)

let default_turbulence amount = { amount; octaves = 6; omega = 0.5; lambda = 2. }
let is_block = function Checker | Hexagon | Brick _ -> true | _ -> false
let block_count = function Hexagon -> 3 | _ -> 2
let eps = 1e-10
let frac x = x -. Float.floor x
let two_pi = 2. *. Float.pi

let checker (p : Vec3.t) =
  let s =
    int_of_float (Float.floor (p.x +. eps))
    + int_of_float (Float.floor (p.y +. eps))
    + int_of_float (Float.floor (p.z +. eps))
  in
  if s land 1 = 0 then 0. else 1.

(* Hexagons in the xz plane, side 1, corners along x (flat sides facing
   +-z), centred at the origin (cell 0); cells around are numbered as
   POV-Ray does: (2q + r) mod 3 in axial coordinates. *)
let sqrt3 = Float.sqrt 3.

let hexagon (p : Vec3.t) =
  (* axial coordinates of the nearest hexagon centre (pointy along x) *)
  let q = p.x *. 2. /. 3. and r = ((-.p.x /. 3.) +. (sqrt3 /. 3. *. p.z)) in
  let s = -.q -. r in
  let rq = Float.round q and rr = Float.round r and rs = Float.round s in
  let dq = Float.abs (rq -. q) and dr = Float.abs (rr -. r) and ds = Float.abs (rs -. s) in
  let rq, rr =
    if dq > dr && dq > ds then (-.rr -. rs, rr)
    else if dr > ds then (rq, -.rq -. rs)
    else (rq, rr)
  in
  let c = ((2 * int_of_float rq) + int_of_float rr) mod 3 in
  float_of_int (if c < 0 then c + 3 else c)

(* Bricks of [size] with mortar of width [mortar] at the upper end of
   each cell; even rows (in y) shift z by half a brick, odd rows shift x
   (found by sampling POV-Ray's pattern). *)
let brick (size : Vec3.t) mortar (p : Vec3.t) =
  let row = Float.floor (p.y /. size.y) in
  let odd = Float.rem (Float.abs row) 2. = 1. in
  let x = if odd then p.x +. (size.x /. 2.) else p.x in
  let z = if odd then p.z else p.z +. (size.z /. 2.) in
  let in_mortar c s = frac (c /. s) *. s >= s -. mortar in
  if in_mortar x size.x || in_mortar p.y size.y || in_mortar z size.z then 0. else 1.

(* Wave sources of ripples and waves: fixed pseudo-random points. *)
let sources =
  Array.init 10 (fun i ->
      let f k = Noise.snoise (Vec3.make (float_of_int i +. 0.37) (float_of_int k +. 0.71) 0.53) in
      Vec3.scale 2. (Vec3.make (f 1) (f 2) (f 3)))

let clamp01 x = Float.min 1. (Float.max 0. x)

(* One feature point per unit cell, placed by hashing the cell with the
   noise (camlray's own cellular noise: POV-Ray's points differ). *)
let feature ix iy iz =
  let c = Vec3.make (float_of_int ix) (float_of_int iy) (float_of_int iz) in
  let h k = 0.5 +. (0.5 *. Noise.snoise (Vec3.make (c.x +. 0.31 +. k) (c.y +. 0.47) (c.z +. 0.73 -. k))) in
  Vec3.add c (Vec3.make (h 0.) (h 17.3) (h 41.9))

(* crackle: distance to the second nearest feature point minus the
   nearest (POV-Ray's default form <-1, 1, 0>) *)
let crackle (p : Vec3.t) =
  let fx = int_of_float (Float.floor p.x) and fy = int_of_float (Float.floor p.y)
  and fz = int_of_float (Float.floor p.z) in
  let d1 = ref infinity and d2 = ref infinity in
  for i = -1 to 1 do
    for j = -1 to 1 do
      for k = -1 to 1 do
        let d = Vec3.dist p (feature (fx + i) (fy + j) (fz + k)) in
        if d < !d1 then (d2 := !d1; d1 := d) else if d < !d2 then d2 := d
      done
    done
  done;
  clamp01 (!d2 -. !d1)

let raw kind (p : Vec3.t) =
  match kind with
  | Checker -> checker p
  | Hexagon -> hexagon p
  | Brick { size; mortar } -> brick size mortar p
  | Gradient v -> Vec3.dot p v
  | Radial -> -.Float.atan2 p.z p.x /. two_pi
  | Onion -> Vec3.length p
  | Wood -> Float.sqrt ((p.x *. p.x) +. (p.y *. p.y))
  | Marble -> p.x
  | Leopard ->
      let s = (Float.sin p.x +. Float.sin p.y +. Float.sin p.z) /. 3. in
      s *. s
  | Bozo | Spotted | Bumps -> Noise.noise p
  | Dents ->
      let n = Noise.noise p in
      n *. n *. n
  | Granite ->
      (* affine-matched to the mean and spread of POV-Ray's granite values *)
      clamp01 (0.015 +. (1.726 *. 0.5 *. Noise.fractal ~octaves:6 (Vec3.scale 4. p)))
  | Agate turb ->
      let t = Noise.fractal ~octaves:7 p in
      let v = 0.5 +. (0.5 *. Float.sin (two_pi *. (p.z +. (turb *. t)))) in
      Float.pow v 0.77
  | Ripples | Waves ->
      let acc = ref 0. in
      Array.iter
        (fun c ->
          let d = Vec3.dist p c in
          acc :=
            !acc
            +.
            match kind with
            | Ripples -> 0.5 +. (0.5 *. Float.sin (two_pi *. d))
            | _ -> 0.5 +. (0.5 *. Float.cos (two_pi *. d)))
        sources;
      !acc /. float_of_int (Array.length sources)
  | Crackle -> crackle p
  | Wrinkles -> clamp01 (0.165 +. (1.584 *. 0.5 *. Noise.fractal ~octaves:10 p))

let default_wave = function Wood | Marble -> Triangle | _ -> Ramp

let shape wave v =
  match wave with
  | Ramp -> v
  | Triangle -> if v < 0.5 then 2. *. v else 2. *. (1. -. v)
  | Sine -> 0.5 +. (0.5 *. Float.sin (two_pi *. v))
  | Scallop -> Float.abs (Float.sin (Float.pi *. v))
  | Cubic -> v *. v *. (3. -. (2. *. v))
  | Poly e -> Float.pow v e

let value t p =
  let p =
    match t.turbulence with
    | None -> p
    | Some tb ->
        let d = Noise.turbulence ~octaves:tb.octaves ~omega:tb.omega ~lambda:tb.lambda p in
        Vec3.add p (Vec3.mul d tb.amount)
  in
  let v = raw t.kind p in
  if is_block t.kind then v
  else
    let v = Float.rem ((v *. t.frequency) +. t.phase) 1.00001 in
    let v = if v < 0. then v +. 1. else v in
    let v = Float.min 1. v in
    shape (Option.value ~default:(default_wave t.kind) t.wave) v

(* [checker] at a point written in place: 0 or 1 *)
let checker_m (p : Vec3.m) =
  (int_of_float (Float.floor (p.mx +. eps))
  + int_of_float (Float.floor (p.my +. eps))
  + int_of_float (Float.floor (p.mz +. eps)))
  land 1
