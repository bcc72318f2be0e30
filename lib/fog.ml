(* POV-Ray's fog (see fog.mli). *)

type kind = Constant | Ground of { offset : float; alt : float; up : Vec3.t }
type turbulence = { amount : Vec3.t; depth : float; octaves : int; omega : float; lambda : float }
type t = { kind : kind; distance : float; color : Color.rgbft; turbulence : turbulence option }

let missed = 2e10

(* [width] thinned by the turbulence (POV-Ray 3.7's ComputeConstantFog
   and ComputeGroundFog, in their order of operations): the Turbulence
   (the scene's noise generator) at the point halfway along the ray
   ([o] + width/2 [d] for a constant fog, the mean of the two ends for a
   ground fog), scaled per axis by the amount, times turb_depth, at most
   1, weighs the fog's own transmittance over [width] *)
let[@inline] thinned f ground (o : Vec3.m) (d : Vec3.m) width =
  match f.turbulence with
  | None -> width
  | Some u ->
      let a = u.amount and h = width /. 2. in
      let x = if ground then (o.mx +. (o.mx +. (d.mx *. width))) *. 0.5 else o.mx +. (h *. d.mx) in
      let y = if ground then (o.my +. (o.my +. (d.my *. width))) *. 0.5 else o.my +. (h *. d.my) in
      let z = if ground then (o.mz +. (o.mz +. (d.mz *. width))) *. 0.5 else o.mz +. (h *. d.mz) in
      let k = Float.exp (-.width /. f.distance) in
      let t =
        Noise.turbulence !Pattern.scene_noise_generator ~octaves:u.octaves ~omega:u.omega ~lambda:u.lambda (x *. a.x)
          (y *. a.y) (z *. a.z)
      in
      width *. (1. -. (k *. Float.min 1. (t *. u.depth)))

(* the mean density of a ground fog between the altitudes [s] and [e]
   (in units of [alt] above [offset]): 1 below 0, 1 / (1 + h^2) above,
   whose integral is atan *)
let[@inline] mean_density s e =
  if s <= 0. then if e <= 0. then 1. else (Float.atan e -. s) /. (e -. s)
  else if e <= 0. then (Float.atan s -. e) /. (s -. e)
  else
    let delta = s -. e in
    if Float.abs delta > 1e-10 then (Float.atan s -. Float.atan e) /. delta else 1. /. ((s *. s) +. 1.)

let[@inline] transmittance f (o : Vec3.m) (d : Vec3.m) width =
  match f.kind with
  | Constant ->
      let w = thinned f false o d width in
      Float.exp (-.w /. f.distance)
  | Ground { offset; alt; up } ->
      let y1 = (o.mx *. up.x) +. (o.my *. up.y) +. (o.mz *. up.z) in
      let y2 = y1 +. (width *. ((d.mx *. up.x) +. (d.my *. up.y) +. (d.mz *. up.z))) in
      let density = mean_density ((y1 -. offset) /. alt) ((y2 -. offset) /. alt) in
      let w = thinned f true o d width in
      Float.exp (-.w *. density /. f.distance)

(* per domain: the ray's unit direction, and the fogs' running product
   of attenuations and sum of colours (r, g, b each), then the width of
   fog crossed (kept there, not passed: a float argument is boxed) *)
type work = { u : Vec3.m; sums : Float.Array.t }

let work_key = Scratch.key (fun () -> { u = Vec3.m (); sums = Float.Array.make 7 0. })

let rec through fogs (o : Vec3.m) (w : work) =
  match fogs with
  | [] -> ()
  | f :: rest ->
      if Float.abs f.distance > 1e-10 then begin
        let fc = f.color and s = w.sums in
        let width = Float.Array.get s 6 in
        let a = Float.max fc.transmit (transmittance f o w.u width) in
        let flt = fc.filter in
        for i = 0 to 2 do
          let c = match i with 0 -> fc.c.r | 1 -> fc.c.g | _ -> fc.c.b in
          Float.Array.set s i (Float.Array.get s i *. a *. (1. -. flt +. (flt *. c)));
          Float.Array.set s (i + 3) (Float.Array.get s (i + 3) +. ((1. -. a) *. c))
        done
      end;
      through rest o w

let apply fogs (o : Vec3.m) (d : Vec3.m) t (c : Color.acc) =
  let dl = Float.sqrt ((d.mx *. d.mx) +. (d.my *. d.my) +. (d.mz *. d.mz)) in
  let w = Scratch.get work_key in
  Vec3.set w.u (d.mx /. dl) (d.my /. dl) (d.mz /. dl);
  let s = w.sums in
  Float.Array.fill s 0 3 1.;
  Float.Array.fill s 3 3 0.;
  Float.Array.set s 6 (if t = infinity then missed else t *. dl);
  through fogs o w;
  Color.acc_set c
    (Float.Array.get s 3 +. (Float.Array.get s 0 *. c.ar))
    (Float.Array.get s 4 +. (Float.Array.get s 1 *. c.ag))
    (Float.Array.get s 5 +. (Float.Array.get s 2 *. c.ab))

(* the fogs' attenuation and added colour over [width] units (infinity:
   a ray that met nothing) from [o] along the unit vector [d] *)
let blend_into fogs (o : Vec3.m) (d : Vec3.m) width (att : Color.acc) (add : Color.acc) =
  let w = Scratch.get work_key in
  Vec3.set w.u d.mx d.my d.mz;
  let s = w.sums in
  Float.Array.fill s 0 3 1.;
  Float.Array.fill s 3 3 0.;
  Float.Array.set s 6 (if width = infinity then missed else width);
  through fogs o w;
  Color.acc_set att (Float.Array.get s 0) (Float.Array.get s 1) (Float.Array.get s 2);
  Color.acc_set add (Float.Array.get s 3) (Float.Array.get s 4) (Float.Array.get s 5)

let[@inline] dim fogs (o : Vec3.m) (d : Vec3.m) width (c : Color.acc) =
  let w = Scratch.get work_key in
  Vec3.set w.u d.mx d.my d.mz;
  let s = w.sums in
  Float.Array.fill s 0 3 1.;
  Float.Array.fill s 3 3 0.;
  Float.Array.set s 6 width;
  through fogs o w;
  Color.acc_set c (Float.Array.get s 0 *. c.ar) (Float.Array.get s 1 *. c.ag) (Float.Array.get s 2 *. c.ab)
