(* Rainbows (see rainbow.mli). *)

type t = {
  angle : float;  (** radians, less half the width: the map's 0 *)
  width : float;  (** radians *)
  distance : float;
  jitter : float;
  dir : Vec3.t;  (** antisolar, unit *)
  up : Vec3.t;  (** unit, square to [dir] *)
  right : Vec3.t;
  arc : float;  (** half the arc angle, radians (or 180: see make) *)
  falloff : float;
  falloff_width : float;
  pigment : Pigment.t;
}

let make ~angle ~width ~distance ~jitter ~direction ~up ~arc ~falloff pigment =
  let dir = Vec3.normalize direction in
  let up = Vec3.normalize up in
  (* up made square to the direction, as POV-Ray does *)
  let right = Vec3.normalize (Vec3.cross up dir) in
  let up = Vec3.normalize (Vec3.cross dir right) in
  let rad = Float.pi /. 180. in
  { angle = (angle -. (0.5 *. width)) *. rad; width = width *. rad; distance; jitter; dir; up; right; arc; falloff;
    falloff_width = arc -. falloff; pigment }

let drawn r = r.distance <> 0. && r.width <> 0.

(* per domain: the map's point and colour, the sum of the rainbows, the
   distance (held here: a float argument would be boxed) *)
type work = { q : Vec3.m; c : Pigment.out; sum : Color.acc; t : Float.Array.t }

let work_key = Scratch.key (fun () -> { q = Vec3.m (); c = Pigment.out (); sum = Color.acc 0.; t = Float.Array.make 1 0. })

(* a number in [-1, 1) from the direction's bits: the same for the same
   ray on every run *)
let[@inline] mix h x =
  let b = Int64.bits_of_float x in
  let h = (h lxor Int64.to_int b lxor Int64.to_int (Int64.shift_right_logical b 32)) * 0x9E3779B1 in
  h lxor (h lsr 15)

(* inlined: its float result stays unboxed *)
let[@inline] hash_unit (d : Vec3.m) =
  let h = mix (mix (mix 0x2545F491 d.mx) d.my) d.mz in
  (float_of_int (h land 0xFFFFFF) /. float_of_int 0x800000) -. 1.

(* rainbow [r] at the ray, added into [w.sum] from the light [c]: whether
   it is drawn there *)
let one r (d : Vec3.m) (c : Color.acc) w =
  drawn r
  &&
  let x = (d.mx *. r.right.x) +. (d.my *. r.right.y) +. (d.mz *. r.right.z)
  and y = (d.mx *. r.up.x) +. (d.my *. r.up.y) +. (d.mz *. r.up.z) in
  let l = Float.sqrt ((x *. x) +. (y *. y)) in
  let y = if l > 0. then y /. l else y in
  let around = Float.abs (Float.acos (Float.min 1. (Float.max (-1.) y))) in
  around <= r.arc
  &&
  let dot = (d.mx *. r.dir.x) +. (d.my *. r.dir.y) +. (d.mz *. r.dir.z) in
  dot >= 0.
  &&
  let index = (Float.acos (Float.min 1. dot) -. r.angle) /. r.width in
  let index = if r.jitter > 0. then index +. (hash_unit d *. r.jitter) else index in
  index >= 0. && index <= 1. -. 1e-10
  && begin
    Vec3.set w.q index 0. 0.;
    let cr = w.c and sum = w.sum in
    Pigment.into r.pigment w.q cr;
    let fade =
      if r.falloff_width > 0. && around > r.falloff then
        let f = (around -. r.falloff) /. r.falloff_width in
        (3. -. (2. *. f)) *. f *. f
      else 0.
    in
    let k = Float.exp (-.Float.Array.get w.t 0 /. r.distance) in
    (* the colour's transmit is the least that comes through *)
    let k = Float.max k ((fade *. (1. -. cr.transmit)) +. cr.transmit) in
    let ki = 1. -. k in
    let f = cr.filter *. ki in
    Color.acc_set sum
      (sum.ar +. (k *. c.ar *. ((1. -. f) +. (f *. cr.r))) +. (ki *. cr.r))
      (sum.ag +. (k *. c.ag *. ((1. -. f) +. (f *. cr.g))) +. (ki *. cr.g))
      (sum.ab +. (k *. c.ab *. ((1. -. f) +. (f *. cr.b))) +. (ki *. cr.b));
    true
  end

(* how many of [rainbows] are seen along [d], each laid into [w.sum] *)
let rec count rainbows d c w n =
  match rainbows with [] -> n | r :: rest -> count rest d c w (if one r d c w then n + 1 else n)

let apply rainbows (d : Vec3.m) t (c : Color.acc) =
  let w = Scratch.get work_key in
  Float.Array.set w.t 0 t;
  let sum = w.sum in
  Color.acc_set sum 0. 0. 0.;
  let n = count rainbows d c w 0 in
  if n > 0 then begin
    let k = 1. /. float_of_int n in
    Color.acc_set c (k *. sum.ar) (k *. sum.ag) (k *. sum.ab)
  end

(* [apply] is affine in the light: [a] and [b] such that the light [c]
   becomes a c + b, for a path tracer's throughput *)
let layer rainbows (d : Vec3.m) t (a : Color.acc) (b : Color.acc) =
  Color.acc_set b 0. 0. 0.;
  apply rainbows d t b;
  Color.acc_set a 1. 1. 1.;
  apply rainbows d t a;
  Color.acc_set a (a.ar -. b.ar) (a.ag -. b.ag) (a.ab -. b.ab)
