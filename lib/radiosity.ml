(* POV-Ray 3.7's radiosity: settings, gather directions, per-domain
   depth (see radiosity.mli). *)

type t = {
  count : int;
  recursion_limit : int;
  brightness : float;
  error_bound : float;
  nearest_count : int;
  gray_threshold : float;
  pretrace_start : float;
  pretrace_end : float;
  low_error_factor : float;
  minimum_reuse : float;
  maximum_reuse : float;
  adc_bailout : float;
  max_sample : float;
  always_sample : bool;
  normal : bool;
  media : bool;
  keep_ambient : bool;
}

let default =
  {
    count = 35;
    recursion_limit = 2;
    brightness = 1.;
    error_bound = 1.8;
    nearest_count = 5;
    gray_threshold = 0.;
    pretrace_start = 0.08;
    pretrace_end = 0.04;
    low_error_factor = 0.5;
    minimum_reuse = 0.015;
    maximum_reuse = 0.2;
    adc_bailout = 0.01;
    max_sample = -1.;
    always_sample = false;
    normal = false;
    media = false;
    keep_ambient = false;
  }

let rays r depth = Int.max 5 (int_of_float (float_of_int r.count *. Float.pow 0.5 (float_of_int depth)))
let trace_level depth = int_of_float (1.5 *. float_of_int (depth + 1)) + 1
let weight r depth = Float.max (r.adc_bailout +. 1e-10) (Float.pow (0.5 *. r.brightness) (float_of_int (depth + 1)))

let radical_inverse i =
  (* the bits of i mirrored about the binary point *)
  let rec go i f acc = if i = 0 then acc else go (i lsr 1) (f *. 0.5) (if i land 1 = 1 then acc +. f else acc) in
  go i 0.5 0.

let[@inline] frac x = x -. Float.floor x

let direction_into (n : Vec3.m) i count r1 r2 (out : Vec3.m) =
  let u1 = frac (((float_of_int i +. 0.5) /. float_of_int count) +. r1) in
  let u2 = frac (radical_inverse i +. r2) in
  let rad = Float.sqrt u1 and phi = 2. *. Float.pi *. u2 in
  let lx = rad *. Float.cos phi and lz = rad *. Float.sin phi in
  let ly = Float.sqrt (Float.max 0. (1. -. u1)) in
  (* POV-Ray's frame: y the normal, x across it and z (or y), z = x × y *)
  let near_z = Float.abs n.mz > 0.9 in
  let oy = if near_z then 1. else 0. and oz = if near_z then 0. else 1. in
  let xx = (n.my *. oz) -. (n.mz *. oy) and xy = -.(n.mx *. oz) and xz = n.mx *. oy in
  let k = 1. /. Float.sqrt ((xx *. xx) +. (xy *. xy) +. (xz *. xz)) in
  let xx = xx *. k and xy = xy *. k and xz = xz *. k in
  let zx = (xy *. n.mz) -. (xz *. n.my) and zy = (xz *. n.mx) -. (xx *. n.mz) and zz = (xx *. n.my) -. (xy *. n.mx) in
  Vec3.set out
    ((lx *. xx) +. (ly *. n.mx) +. (lz *. zx))
    ((lx *. xy) +. (ly *. n.my) +. (lz *. zy))
    ((lx *. xz) +. (ly *. n.mz) +. (lz *. zz))

let depth_key = Scratch.key (fun () -> ref 0)
let depth () = !(Scratch.get depth_key)
let descend () = incr (Scratch.get depth_key)
let ascend () = decr (Scratch.get depth_key)
let reset_depth () = Scratch.get depth_key := 0
