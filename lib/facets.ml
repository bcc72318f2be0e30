(* POV-Ray 3.7's facets normal (normal.cpp, [facets]), over crackle's
   feature points ({!Pattern.feature_point}) and POV-Ray's DNoise. *)

type t = { size : float; coords : float; metric : float }

let default = { size = 0.1; coords = 0.; metric = 2. }

(* The cubes searched around the one holding the point: crackle's 81
   (offsets -2 .. 2 on each axis, at most one of them +-2, in POV-Ray's
   order), as x, y, z triples *)
let offsets = Pattern.crackle_cubes

let count = Array.length offsets / 3

(* Per domain: the feature points of the cubes around the last cube
   asked for (they depend on nothing else, so every facets normal shares
   them, as POV-Ray's thread cache does), and a vector to work in. *)
type cache = {
  pts : Float.Array.t;  (** [count] points, x, y, z *)
  mutable cx : int;
  mutable cy : int;
  mutable cz : int;
  mutable filled : bool;
  v : Vec3.m;
}

let cache_key =
  Scratch.key (fun () ->
      { pts = Float.Array.make (3 * count) 0.; cx = 0; cy = 0; cz = 0; filled = false; v = Vec3.m () })

(* POV-Ray's PickInCube: the cube holding [t] is the one below [t] less
   1e-10 (POV-Ray's EPSILON), on each axis *)
let[@inline] cube t = Float.floor (t -. 1e-10)

(* The points of the cubes around the point (tx, ty, tz), each cube found
   from the point moved by the offset, as POV-Ray does *)
let fill c tx ty tz ix iy iz =
  for i = 0 to count - 1 do
    let o = 3 * i in
    Pattern.feature_point
      (cube (tx +. float_of_int (Array.unsafe_get offsets o)))
      (cube (ty +. float_of_int (Array.unsafe_get offsets (o + 1))))
      (cube (tz +. float_of_int (Array.unsafe_get offsets (o + 2))))
      c.v;
    Float.Array.unsafe_set c.pts o c.v.mx;
    Float.Array.unsafe_set c.pts (o + 1) c.v.my;
    Float.Array.unsafe_set c.pts (o + 2) c.v.mz
  done;
  c.cx <- ix;
  c.cy <- iy;
  c.cz <- iz;
  c.filled <- true

(* The index of the point nearest (tx, ty, tz) in the metric: 2 the
   squared distance, 1 the sum of the differences (signed, as POV-Ray
   writes it), else the sum of their magnitudes to the power [m]; the
   first of equals. *)
let nearest c m tx ty tz =
  let best = ref 0 and least = ref infinity in
  for i = 0 to count - 1 do
    let o = 3 * i in
    let dx = Float.Array.unsafe_get c.pts o -. tx
    and dy = Float.Array.unsafe_get c.pts (o + 1) -. ty
    and dz = Float.Array.unsafe_get c.pts (o + 2) -. tz in
    let d =
      if m = 2. then (dx *. dx) +. (dy *. dy) +. (dz *. dz)
      else if m = 1. then dx +. dy +. dz
      else Float.pow (Float.abs dx) m +. Float.pow (Float.abs dy) m +. Float.pow (Float.abs dz) m
    in
    if d < !least then begin
      least := d;
      best := i
    end
  done;
  !best

let tilt_m f (q : Vec3.m) (n : Vec3.m) (out : Vec3.m) =
  let c = Scratch.get cache_key in
  let s = if f.size < 1e-6 then 1e6 else 1. /. f.size in
  let coords = f.coords <> 0. in
  let from = if coords then q else n in
  let tx = from.mx *. s and ty = from.my *. s and tz = from.mz *. s in
  let ix = int_of_float (cube tx) and iy = int_of_float (cube ty) and iz = int_of_float (cube tz) in
  if not (c.filled && c.cx = ix && c.cy = iy && c.cz = iz) then fill c tx ty tz ix iy iz;
  let o = 3 * nearest c f.metric tx ty tz in
  let px = Float.Array.unsafe_get c.pts o and py = Float.Array.unsafe_get c.pts (o + 1)
  and pz = Float.Array.unsafe_get c.pts (o + 2) in
  if coords then begin
    (* POV-Ray's DNoise at the point, less its part along the normal *)
    Noise.dnoise px py pz c.v;
    let d = (c.v.mx *. n.mx) +. (c.v.my *. n.my) +. (c.v.mz *. n.mz) in
    let k = f.coords in
    Vec3.set out
      (n.mx +. (k *. (c.v.mx -. (d *. n.mx))))
      (n.my +. (k *. (c.v.my -. (d *. n.my))))
      (n.mz +. (k *. (c.v.mz -. (d *. n.mz))))
  end
  else Vec3.set out px py pz
