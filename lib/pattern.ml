type wave = Ramp | Triangle | Sine | Scallop | Cubic | Poly of float

type fractal = {
  iterations : int;
  exponent : int;
  exterior : int;
  efactor : float;
  interior : int;
  ifactor : float;
}

(* a function's code and where it leaves its value; its frames (of the
   function's size), one per domain *)
type fn = { result : int; run : float array -> unit; frames : float array Scratch.key }

let fn ~slots ~result run =
  if slots < 3 || result < 0 || result >= slots then invalid_arg "Pattern.fn: bad slot counts";
  { result; run; frames = Scratch.key (fun () -> Array.make slots 0.) }

type inside = { test : Vec3.m -> bool }

let inside test = { test }

type crackle = { form : Vec3.t; metric : float; offset : float; solid : bool }

let crackle_default = { form = Vec3.make (-1.) 1. 0.; metric = 2.; offset = 0.; solid = false }

type kind =
  | Checker
  | Hexagon
  | Brick of { size : Vec3.t; mortar : float }
  | Gradient of Vec3.t
  | Radial
  | Onion
  | Planar
  | Spherical
  | Boxed
  | Cylindrical
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
  | Crackle of crackle
  | Spiral1 of int
  | Spiral2 of int
  | Quilted of { c0 : float; c1 : float }
  | Mandel of fractal
  | Julia of { cr : float; ci : float; fractal : fractal }
  | Magnet of { formula : int; julia : bool; cr : float; ci : float; fractal : fractal }
  | Slope of { dir : Vec3.t; lo : float; hi : float; wdir : float; alt : Vec3.t; alo : float; ahi : float; walt : float }
  | Cells
  | Tiling of int
  | Object of inside
  | Material of { w : int; h : int; once : bool; numbers : Bytes.t; count : int }
  | Function of fn
  | Density_file of density
  | Image of Bump_map.t

and density = { nx : int; ny : int; nz : int; voxels : Float.Array.t; interpolate : int }

(* df3: three big-endian 16-bit sizes, then the voxels (x fastest), of 1,
   2 or 4 big-endian bytes each, as fractions of their largest value *)
let read_df3 path =
  let d = In_channel.with_open_bin path In_channel.input_all in
  if String.length d < 6 then failwith "not a df3 file (shorter than its 6-byte header)";
  let u16 i = (Char.code d.[i] lsl 8) lor Char.code d.[i + 1] in
  let nx = u16 0 and ny = u16 2 and nz = u16 4 in
  let n = nx * ny * nz in
  if n = 0 then failwith (Printf.sprintf "a df3 file of %dx%dx%d voxels" nx ny nz);
  let bytes = String.length d - 6 in
  let size = bytes / n in
  if bytes mod n <> 0 || not (size = 1 || size = 2 || size = 4) then
    failwith (Printf.sprintf "%d bytes of data for %dx%dx%d voxels (1, 2 or 4 bytes each)" bytes nx ny nz);
  let top = Float.pow 2. (float_of_int (8 * size)) -. 1. in
  let voxels =
    Float.Array.init n (fun k ->
        let v = ref 0 in
        for b = 0 to size - 1 do
          v := (!v lsl 8) lor Char.code d.[6 + (k * size) + b]
        done;
        float_of_int !v /. top)
  in
  { nx; ny; nz; voxels; interpolate = 0 }

(* POV-Ray's density_file: the unit cube [0, 1)^3, 0 outside; the voxel
   at floor(p * n), or trilinear between it and the next one up (which
   wraps to the first at the far faces) *)
let[@inline] voxel d i j k = Float.Array.unsafe_get d.voxels ((((k * d.ny) + j) * d.nx) + i)

let density3 d x y z =
  if not (x >= 0. && x < 1. && y >= 0. && y < 1. && z >= 0. && z < 1.) then 0.
  else
    let fx = x *. float_of_int d.nx and fy = y *. float_of_int d.ny and fz = z *. float_of_int d.nz in
    let i1 = Int.min (d.nx - 1) (int_of_float fx) and j1 = Int.min (d.ny - 1) (int_of_float fy)
    and k1 = Int.min (d.nz - 1) (int_of_float fz) in
    if d.interpolate = 0 then voxel d i1 j1 k1
    else
      let i2 = (i1 + 1) mod d.nx and j2 = (j1 + 1) mod d.ny and k2 = (k1 + 1) mod d.nz in
      let tx = fx -. Float.of_int i1 and ty = fy -. Float.of_int j1 and tz = fz -. Float.of_int k1 in
      let sx = 1. -. tx and sy = 1. -. ty and sz = 1. -. tz in
      (((((voxel d i1 j1 k1 *. sx) +. (voxel d i2 j1 k1 *. tx)) *. sy)
        +. (((voxel d i1 j2 k1 *. sx) +. (voxel d i2 j2 k1 *. tx)) *. ty))
       *. sz)
      +. (((((voxel d i1 j1 k2 *. sx) +. (voxel d i2 j1 k2 *. tx)) *. sy)
           +. (((voxel d i1 j2 k2 *. sx) +. (voxel d i2 j2 k2 *. tx)) *. ty))
          *. tz)

type turbulence = { amount : Vec3.t; octaves : int; omega : float; lambda : float }

type warp_kind =
  | Repeat of { axis : int; width : float; offset : Vec3.t; flip : Vec3.t }
  | Black_hole of {
      center : Vec3.t;
      radius : float;
      strength : float;
      falloff : float;
      inverse : bool;
      repeat : Vec3.t;
      jitter : Vec3.t;
    }
  | Turbulence of turbulence
  | Planar_map of { orient : Vec3.t; offset : float }
  | Spherical_map of { orient : Vec3.t; dist_exp : float }
  | Cylindrical_map of { orient : Vec3.t; dist_exp : float }
  | Toroidal_map of { orient : Vec3.t; dist_exp : float; major : float }

type warp = { kind : warp_kind; into : Transform.t; back : Transform.t }

let warp before kind = { kind; into = Transform.inverse before; back = before }

type t = {
  kind : kind;
  turbulence : turbulence option;
  frequency : float;
  phase : float;
  wave : wave option;
  warps : warp array;
  noise_gen : int;
}

(* quilted and image_pattern start at frequency 0 (POV-Ray's parser
   sets it), their values left unwrapped *)
let make kind =
  let frequency = match kind with Quilted _ | Image _ -> 0. | _ -> 1. in
  { kind; turbulence = None; frequency; phase = 0.; wave = None; warps = [||]; noise_gen = 0 }

let mandel iterations = { iterations; exponent = 2; exterior = 1; efactor = 1.; interior = 0; ifactor = 1. }

let gradient v =
  let l = Vec3.length v in
  Gradient (if l = 0. then Vec3.unit_x else Vec3.scale (1. /. l) v)

(* the scene's noise generator ([global_settings { noise_generator }], 2
   when not given), for the patterns that name none: set by the compiler
   for the scene it compiles, read (never written) while it renders, as
   POV-Ray reads its scene's setting where a pattern has none *)
let scene_noise_generator = ref 2

let[@inline] generator t = if t.noise_gen = 0 then !scene_noise_generator else t.noise_gen

let default_turbulence amount = { amount; octaves = 6; omega = 0.5; lambda = 2. }

(* the turbulence agate reads its octaves, omega and lambda from: its
   classic turbulence, else POV-Ray's default one (agate always has one,
   of amount 0) *)
let agate_turbulence = default_turbulence Vec3.zero
let is_block = function Checker | Hexagon | Brick _ | Object _ | Material _ -> true | _ -> false
let block_count = function Hexagon -> 3 | Material { count; _ } -> count | _ -> 2
let eps = 1e-10
let two_pi = 2. *. Float.pi

(* Each pattern in scalars, inlined into [raw_m]: a call would box its
   floats. The same arithmetic as with vectors (sums left to right). *)
let[@inline] checker3 x y z =
  let s =
    int_of_float (Float.floor (x +. eps))
    + int_of_float (Float.floor (y +. eps))
    + int_of_float (Float.floor (z +. eps))
  in
  if s land 1 = 0 then 0. else 1.

(* Hexagons in the xz plane, side 1, corners along x (flat sides facing
   +-z), centred at the origin (cell 0), by POV-Ray's own construction,
   so that points on an edge fall where POV-Ray puts them: |x|, and a
   negative z moved up by six rows (no mirror image across x); the plane
   cut in a 6 x 6 grid of half-triangles (x in halves, z in the
   triangles' heights, POV-Ray's 0.866025404), most blocks one cell, the
   blocks of columns 1 and 4 split along their diagonal (flipped where
   the slope is negative), the lower half taken by a slope below 1 *)
let[@inline] hex_low zm = if zm = 0 || zm = 3 then 0 else if zm = 2 || zm = 5 then 1 else 2
let[@inline] hex_high zm = if zm = 0 || zm = 3 then 2 else if zm = 2 || zm = 5 then 0 else 1

let[@inline] hexagon3 x z =
  let x = Float.abs x in
  let z = if z < 0. then 5.196152424 -. Float.abs z else z in
  let xs = x /. 0.5 and zs = z /. 0.866025404 in
  let xs = xs -. (Float.floor (xs /. 6.) *. 6.) and zs = zs -. (Float.floor (zs /. 6.) *. 6.) in
  let xm = int_of_float (Float.floor xs) mod 6 and zm = int_of_float (Float.floor zs) mod 6 in
  let c =
    if xm = 0 || xm = 5 then if zm = 0 || zm = 5 then 0 else if zm <= 2 then 1 else 2
    else if xm = 2 || xm = 3 then if zm <= 1 then 2 else if zm <= 3 then 0 else 1
    else begin
      let xl = xs -. float_of_int xm and zl = zs -. float_of_int zm in
      let xl = if (xm + zm) mod 2 = 1 then 1. -. xl else xl in
      let xl = if xl = 0. then 0.0001 else xl in
      if zl /. xl < 1. then hex_low zm else hex_high zm
    end
  in
  float_of_int c

(* Bricks of [size] with mortar of width [mortar], as POV-Ray 3.7 lays
   them: the point is moved by mortar + 1e-10 on every axis, and a
   coordinate is in the mortar where its fraction of the brick's size is
   at most mortar / size; so the mortar fills the last [mortar] of each
   cell, shifted down by 1e-10 (measured with povray 3.7 to the last
   bits: 7.5 - 0.9e-10 is mortar, 7.5 - 1.1e-10 brick, for the default
   bricks). Rows whose half count's fraction is at most 0.5 have their
   ends at whole multiples of x and their faces between those of z;
   the others the other way round. *)
let[@inline] brick_frac v =
  let f = v -. Float.of_int (Float.to_int v) in
  if f < 0. then f +. 1. else f

let[@inline] brick3 (size : Vec3.t) mortar x y z =
  let fudge = 1e-10 +. mortar in
  let x = x +. fudge and y = y +. fudge and z = z +. fudge in
  if brick_frac (y /. size.y) <= mortar /. size.y then 0.
  else begin
    let lower = brick_frac (y /. size.y *. 0.5) <= 0.5 in
    let mx = mortar /. size.x and mz = mortar /. size.z in
    if lower && brick_frac (x /. size.x) <= mx then 0.
    else if (not lower) && brick_frac ((x /. size.x) +. 0.5) <= mx then 0.
    else if (not lower) && brick_frac (z /. size.z) <= mz then 0.
    else if lower && brick_frac ((z /. size.z) +. 0.5) <= mz then 0.
    else 1.
  end

(* POV-Ray's sine of a value in turns (texture.cpp's cycloidal): the
   fraction of [v] (for a negative [v] the fraction of -v, the sine
   negated) scaled up and down by 50000 before it is turned into radians,
   as POV-Ray does (the round trip changes the last bits) *)
let[@inline] cycloidal v =
  if v >= 0. then Float.sin ((v -. Float.floor v) *. 50000. /. 50000. *. two_pi)
  else 0. -. Float.sin ((0. -. (v +. Float.floor (0. -. v))) *. 50000. /. 50000. *. two_pi)

(* The wave sources and frequencies of ripples and waves, as POV-Ray 3.7
   makes them (texture.cpp's Initialize_Waves): source i is DNoise at
   (i, 0, 0), normalised (each component divided by the length); its
   frequency is 0.01 + 0.000030518509476 times the 15 bits the C
   library's congruence (x <- 1812433253 x + 12345 on 32 bits) draws, in
   turn from the seed -560851967. [src]: x, y, z per source. *)
type waves = { count : int; src : Float.Array.t; freq : Float.Array.t }

let make_waves n =
  let src = Float.Array.make (3 * n) 0. and freq = Float.Array.make n 0. in
  let v = Vec3.m () in
  let s = ref (-560851967 land 0xFFFF_FFFF) in
  for i = 0 to n - 1 do
    Noise.dnoise (float_of_int i) 0. 0. v;
    let l = Float.sqrt ((v.mx *. v.mx) +. (v.my *. v.my) +. (v.mz *. v.mz)) in
    let l = if l = 0. then 1. else l in
    Float.Array.set src (3 * i) (v.mx /. l);
    Float.Array.set src ((3 * i) + 1) (v.my /. l);
    Float.Array.set src ((3 * i) + 2) (v.mz /. l);
    s := Cells.lcg !s;
    Float.Array.set freq i ((float_of_int (Cells.draw15 !s) *. 0.000030518509476) +. 0.01)
  done;
  { count = n; src; freq }

(* the scene's waves ([global_settings { number_of_waves }], 10 when not
   given): set by the compiler, only read while rendering *)
let scene_waves = ref (make_waves 10)

let set_number_of_waves n =
  let n = Int.max 1 n in
  if n <> !scene_waves.count then scene_waves := make_waves n

let[@inline] waves () = !scene_waves

(* POV-Ray's crackle and facets points (IntPickInCube, PickInCube): one
   per unit cube, at the cube's corner plus three of POV-Ray's pattern
   random numbers (its RandomDoubleSequence, the same table as cells':
   {!Cells.values}), taken from the slot the cube hashes to and the two
   after it *)
let[@inline] pick_rand k = Float.Array.unsafe_get Cells.values k

(* the whole point, for the facets normal (inlined: a call would box the
   floats): the cube's corner (cx, cy, cz) are whole numbers *)
let[@inline] feature_point cx cy cz (out : Vec3.m) =
  let seed = Cells.index (int_of_float cx) (int_of_float cy) (int_of_float cz) in
  Vec3.set out (cx +. pick_rand seed) (cy +. pick_rand (seed + 1)) (cz +. pick_rand (seed + 2))

(* the value in a record of its own, flat: a float field of a record with
   other fields is boxed, and each store would allocate *)
type result = Tiling.result = { mutable v : float }

(* The 81 cubes crackle looks in, as offsets from the point's own (x, y,
   z three apiece), in POV-Ray's order: every cube within two in each
   axis, at most one axis two away *)
let crackle_cubes =
  let l = ref [] in
  for ax = -2 to 2 do
    for ay = -2 to 2 do
      for az = -2 to 2 do
        let two a = if abs a = 2 then 1 else 0 in
        if two ax + two ay + two az <= 1 then l := az :: ay :: ax :: !l
      done
    done
  done;
  Array.of_list (List.rev !l)

(* Per domain, the points of the 81 cubes around the last cubes asked
   about, in a few slots picked by a hash of the cube, as POV-Ray keeps
   them (its crackle cache): the samples of a medium along a ray, and
   neighbouring rays, fall in the same cubes, and the points are the
   same numbers however often they are made (each is the cube's corner
   plus the cell's random offset). *)
let crackle_slots = 64

type crackle_cache = { corners : int array; (* 3 a slot, min_int while empty *) points : Float.Array.t (* 243 a slot *) }

let crackle_cache_key =
  Scratch.key (fun () ->
      { corners = Array.make (3 * crackle_slots) min_int; points = Float.Array.make (243 * crackle_slots) 0. })

(* where the points of cube ([fx], [fy], [fz]) start in [c.points],
   made there first if the slot holds another cube's *)
let crackle_points c fx fy fz =
  let slot = ((fx * 73856093) lxor (fy * 19349663) lxor (fz * 83492791)) land (crackle_slots - 1) in
  let k = 3 * slot and o = 243 * slot in
  let cs = c.corners in
  if not (Array.unsafe_get cs k = fx && Array.unsafe_get cs (k + 1) = fy && Array.unsafe_get cs (k + 2) = fz) then begin
    let pts = c.points in
    for i = 0 to 80 do
      let j = 3 * i in
      let cx = fx + Array.unsafe_get crackle_cubes j
      and cy = fy + Array.unsafe_get crackle_cubes (j + 1)
      and cz = fz + Array.unsafe_get crackle_cubes (j + 2) in
      let seed = Cells.index cx cy cz in
      Float.Array.unsafe_set pts (o + j) (float_of_int cx +. pick_rand seed);
      Float.Array.unsafe_set pts (o + j + 1) (float_of_int cy +. pick_rand (seed + 1));
      Float.Array.unsafe_set pts (o + j + 2) (float_of_int cz +. pick_rand (seed + 2))
    done;
    Array.unsafe_set cs k fx;
    Array.unsafe_set cs (k + 1) fy;
    Array.unsafe_set cs (k + 2) fz
  end;
  o

(* the [i]th of the 81 cubes' point's "distance" to (x, y, z), the
   cubes around the one whose points start at [o] in [pts] (POV-Ray's
   sum: squared for metric 2, |dx| + |dy| + |dz| for 1, else the sum of
   |d|^metric) *)
let[@inline] crackle_cube square unity m pts o i x y z =
  let j = o + (3 * i) in
  let dx = Float.Array.unsafe_get pts j -. x
  and dy = Float.Array.unsafe_get pts (j + 1) -. y
  and dz = Float.Array.unsafe_get pts (j + 2) -. z in
  if square then (dx *. dx) +. (dy *. dy) +. (dz *. dz)
  else if unity then Float.abs dx +. Float.abs dy +. Float.abs dz
  else Float.pow (Float.abs dx) m +. Float.pow (Float.abs dy) m +. Float.pow (Float.abs dz) m

(* POV-Ray 3.7's crackle (pattern.cpp), into [r.v]: the three least sums
   over the 81 cubes' points (sorted as POV-Ray sorts them, so that ties
   go its way), the offset added to each in the metric's power, then
   form . (F1, F2, F3) with F the sums taken back to distances, or with
   [solid] the noise at the nearest point; clipped to [0, 1]. Floats
   passed in or returned would be boxed (a crackle normal samples it four
   times a point) *)
let crackle_into (c : crackle) gen (p : Vec3.m) (r : result) =
  let x = p.mx and y = p.my and z = p.mz in
  let fx = int_of_float (Float.floor (x -. 1e-10))
  and fy = int_of_float (Float.floor (y -. 1e-10))
  and fz = int_of_float (Float.floor (z -. 1e-10)) in
  let m = c.metric in
  let square = m = 2. and unity = m = 1. in
  let cache = Scratch.get crackle_cache_key in
  let o = crackle_points cache fx fy fz and pts = cache.points in
  let m1 = ref (crackle_cube square unity m pts o 0 x y z)
  and m2 = ref (crackle_cube square unity m pts o 1 x y z)
  and m3 = ref (crackle_cube square unity m pts o 2 x y z)
  and best = ref 0 in
  if !m2 < !m1 then begin
    let t = !m1 in
    m1 := !m2;
    m2 := t;
    best := 1
  end;
  if !m3 < !m1 then begin
    let t = !m1 in
    m1 := !m3;
    m3 := t;
    best := 2
  end;
  if !m3 < !m2 then begin
    let t = !m2 in
    m2 := !m3;
    m3 := t
  end;
  for i = 3 to 80 do
    let s = crackle_cube square unity m pts o i x y z in
    if s < !m1 then begin
      m3 := !m2;
      m2 := !m1;
      m1 := s;
      best := i
    end
    else if s < !m2 then begin
      m3 := !m2;
      m2 := s
    end
    else if s < !m3 then m3 := s
  done;
  let o = c.offset in
  if o <> 0. then begin
    let k = if square then o *. o else if unity then o else Float.pow o m in
    m1 := !m1 +. k;
    m2 := !m2 +. k;
    m3 := !m3 +. k
  end;
  let f = c.form in
  let v =
    if c.solid then begin
      let b = 3 * !best in
      let cx = fx + Array.unsafe_get crackle_cubes b
      and cy = fy + Array.unsafe_get crackle_cubes (b + 1)
      and cz = fz + Array.unsafe_get crackle_cubes (b + 2) in
      let seed = Cells.index cx cy cz in
      Noise.noise gen
        (float_of_int cx +. pick_rand seed)
        (float_of_int cy +. pick_rand (seed + 1))
        (float_of_int cz +. pick_rand (seed + 2))
    end
    else if square then (f.x *. Float.sqrt !m1) +. (f.y *. Float.sqrt !m2) +. (f.z *. Float.sqrt !m3)
    else if unity then (f.x *. !m1) +. (f.y *. !m2) +. (f.z *. !m3)
    else
      let e = 1. /. m in
      (f.x *. Float.pow !m1 e) +. (f.y *. Float.pow !m2 e) +. (f.z *. Float.pow !m3 e)
  in
  r.v <- Floats.fmax (Floats.fmin v 1.) 0.

(* POV-Ray's triangle wave: 0 at integers, 1 at half-integers *)
let[@inline] tri v =
  let f = if v >= 0. then v -. Float.floor v else v +. 1. +. Float.floor (Float.abs v) in
  if f >= 0.5 then 2. *. (1. -. f) else 2. *. f

(* spiral1's value around the z axis before its wave: height, distance
   to the axis and the angle (0 along -y, growing towards +x), the angle
   scaled by the number of arms; [turb] is the scalar turbulence *)
let[@inline] spiral3 arms turb x y z =
  let r = Float.sqrt ((x *. x) +. (y *. y)) in
  let phi =
    if r = 0. then 0.
    else if x < 0. then (3. *. (Float.pi /. 2.)) -. Float.asin (y /. r)
    else (Float.pi /. 2.) +. Float.asin (y /. r)
  in
  z +. r +. (float_of_int arms *. phi /. two_pi) +. turb

(* quilted: the offset from the cell's centre, scaled by a cubic Bezier
   of its length (ends 0 and 1, inner controls c0 and c1, times
   1/sqrt(3/4)), its mean absolute coordinate *)
let[@inline] quilt_cubic t c0 c1 =
  let it = 1. -. t in
  ((t *. (t *. t)) +. (3. *. t *. (it *. it) *. c0) +. (3. *. (t *. t) *. it *. c1)) *. 1.154700538

let[@inline] quilted3 c0 c1 x y z =
  let vx = x -. Float.floor x -. 0.5 and vy = y -. Float.floor y -. 0.5 and vz = z -. Float.floor z -. 0.5 in
  let t = Float.sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz)) in
  let k = quilt_cubic t c0 c1 in
  (Float.abs (vx *. k) +. Float.abs (vy *. k) +. Float.abs (vz *. k)) /. 3.

(* the shade of a point of the fractal: escaped after [n] iterations at
   (a, b), or never, [m2] the least squared distance to 0 met *)
let[@inline] exterior_shade f n a b =
  let e = f.efactor in
  match f.exterior with
  | 0 -> e
  | 1 -> float_of_int n /. float_of_int f.iterations
  | 2 -> a *. e
  | 3 -> b *. e
  | 4 -> a *. a *. e
  | 5 -> b *. b *. e
  | 6 -> Float.sqrt ((a *. a) +. (b *. b)) *. e
  | 7 ->
      let m = truncate e in
      if m <= 0 then 0. else float_of_int (n mod m) /. e
  | 8 ->
      let m = truncate (1. +. e) in
      if m <= 0 then 0. else float_of_int (n mod m) /. e
  | _ -> 0.

let[@inline] interior_shade f a b m2 =
  let i = f.ifactor in
  match f.interior with
  | 0 -> i
  | 1 -> Float.sqrt m2 *. i
  | 2 -> a *. i
  | 3 -> b *. i
  | 4 -> a *. a *. i
  | 5 -> b *. b *. i
  | 6 -> (a *. a) +. (b *. b *. i) (* sic: POV-Ray scales b^2 only *)
  | _ -> 0.

type work = { p : Vec3.m; d : Vec3.m; r : result; e : Vec3.m }

let work () = { p = Vec3.m (); d = Vec3.m (); r = { v = 0. }; e = Vec3.m () }

(* POV-Ray 3.7's patterns that handle their turbulence themselves
   (HasSpecialTurbulenceHandling: marble, wood): the point their map's
   entries are taken at has none *)
let[@inline] own_turbulence t =
  match (t.kind, t.turbulence) with (Marble | Wood), Some _ -> true | _ -> false

let[@inline] entries_point t w = if own_turbulence t then w.e else w.p

(* The surface normal (world space, unit) at the point being shaded, for
   the slope pattern: set by the shader, per domain *)
let normal_key = Scratch.key (fun () -> Vec3.m ())

let set_normal (n : Vec3.m) =
  let m = Scratch.get normal_key in
  Vec3.set m n.mx n.my n.mz

(* The surface's <u, v, 0> at the point being shaded, for uv-mapped
   pigments, normals and textures: set by the shader, per domain *)
let uv_key = Scratch.key (fun () -> Vec3.m ())

let set_uv u v = Vec3.set (Scratch.get uv_key) u v 0.
let uv_point () = Scratch.get uv_key

(* POV-Ray's signed binomial coefficients for exponents above 4: row e
   holds C(e, k) for k = 0 .. e, negated where i^k is (k = 2, 3 mod 4);
   e up to 33 *)
let binomials =
  Array.init 34 (fun e ->
      let row = Array.make (e + 1) 1. in
      for k = 1 to e do
        row.(k) <- row.(k - 1) *. float_of_int (e - k + 1) /. float_of_int k
      done;
      Array.mapi (fun k c -> if k land 2 <> 0 then -.c else c) row)

(* x^k by the C library's pow, as POV-Ray takes it (products round
   differently); pow gives exactly 1 and x for k = 0 and 1 (x not a
   signalling NaN, which no arithmetic makes), so it is not called for
   them *)
let[@inline] pow_int x k = if k >= 2 then Float.pow x (float_of_int k) else if k = 1 then x else 1.

(* mandel and julia above exponent 4: z <- z^e + c summed by the
   binomial expansion (in POV-Ray's order), as in [fractal_into]; a
   function of its own, so that the pow calls do not make the other
   exponents' loop keep its values on the stack *)
let[@inline never] power_into f ~mandel ~cr ~ci (w : work) =
  let x = w.p.mx and y = w.p.my in
  let cx = if mandel then x else cr and cy = if mandel then y else ci in
  let e = f.exponent and it = f.iterations in
  let coef = binomials.(e) in
  let a = ref x and b = ref y and m2 = ref ((x *. x) +. (y *. y)) in
  let n = ref 0 and escaped = ref (-1) in
  while !n < it do
    let a0 = !a and b0 = !b in
    let re = ref (pow_int a0 e) and im = ref 0. in
    for k = 1 to e do
      let term = Array.unsafe_get coef k *. pow_int a0 (e - k) *. pow_int b0 k in
      if k land 1 = 0 then re := !re +. term else im := !im +. term
    done;
    a := !re +. cx;
    b := !im +. cy;
    let d2 = (!a *. !a) +. (!b *. !b) in
    if d2 < !m2 then m2 := d2;
    if d2 > 4. then (escaped := !n; n := it) else incr n
  done;
  if !escaped >= 0 then w.r.v <- exterior_shade f !escaped !a !b else w.r.v <- interior_shade f !a !b !m2

(* mandel and julia: z <- z^e + c from z = x + iy of the point (c = z
   for mandel, cr + i ci for julia), until |z|^2 > 4 or the iterations
   run out; exponents 2, 3 and 4 written out as POV-Ray does, others by
   [power_into]. [escaped]: the iteration z escaped at, or -1. Not
   inlined into [raw_m], where the loop's values were kept on the stack. *)
let[@inline never] fractal_into f ~mandel ~cr ~ci (w : work) =
  if f.exponent < 2 || f.exponent > 4 then power_into f ~mandel ~cr ~ci w
  else begin
    let x = w.p.mx and y = w.p.my in
    let cx = if mandel then x else cr and cy = if mandel then y else ci in
    let e = f.exponent and it = f.iterations in
    let a = ref x and b = ref y in
    let a2 = ref (x *. x) and b2 = ref (y *. y) in
    let m2 = ref (!a2 +. !b2) in
    let n = ref 0 and escaped = ref (-1) in
    while !n < it do
      let a0 = !a and b0 = !b in
      if e = 2 then begin
        b := (2. *. a0 *. b0) +. cy;
        a := !a2 -. !b2 +. cx
      end
      else if e = 3 then begin
        b := (3. *. !a2 *. b0) -. (!b2 *. b0) +. cy;
        a := (!a2 *. a0) -. (3. *. a0 *. !b2) +. cx
      end
      else begin
        b := (4. *. ((!a2 *. a0 *. b0) -. (a0 *. !b2 *. b0))) +. cy;
        a := (!a2 *. !a2) -. (6. *. !a2 *. !b2) +. (!b2 *. !b2) +. cx
      end;
      a2 := !a *. !a;
      b2 := !b *. !b;
      let d2 = !a2 +. !b2 in
      if d2 < !m2 then m2 := d2;
      if d2 > 4. then (escaped := !n; n := it) else incr n
    done;
    if !escaped >= 0 then w.r.v <- exterior_shade f !escaped !a !b else w.r.v <- interior_shade f !a !b !m2
  end

(* magnet 1 and 2 (POV-Ray's, measured through pigment functions): the
   orbit is done when z is within 0.01 of the fixed point 1 or farther
   than 100 from 0; shaded as mandel's, the least |z|^2 over the
   iterates (not the start). [escaped] as in [fractal_into]. *)
let[@inline never] magnet_into f formula ~julia ~cr ~ci (w : work) =
  let x = w.p.mx and y = w.p.my in
  let zr = ref (if julia then x else 0.) and zi = ref (if julia then y else 0.) in
  let cr = if julia then cr else x and ci = if julia then ci else y in
  (* formula 2's constants: the real parts of c - 1 and c - 2, and (c -
     1)(c - 2) *)
  let c1r = cr -. 1. and c2r = cr -. 2. in
  let kr = (c1r *. c2r) -. (ci *. ci) and ki = (c1r *. ci) +. (ci *. c2r) in
  let m2 = ref (if julia then (x *. x) +. (y *. y) else infinity) in
  let n = ref 0 and escaped = ref (-1) and it = f.iterations in
  while !n < it do
    let a = !zr and b = !zi in
    (* numerator p and denominator q, complex (in local refs: a tuple of
       floats would be allocated) *)
    let pr = ref 0. and pi = ref 0. and qr = ref 0. and qi = ref 0. in
    if formula = 1 then begin
      pr := (a *. a) -. (b *. b) +. cr -. 1.;
      pi := (2. *. a *. b) +. ci;
      qr := (2. *. a) +. cr -. 2.;
      qi := (2. *. b) +. ci
    end
    else begin
      (* z^3 + 3 (c - 1) z + (c - 1)(c - 2) over 3 z^2 + 3 (c - 2) z + (c - 1)(c - 2) + 1 *)
      let a2 = (a *. a) -. (b *. b) and b2 = 2. *. a *. b in
      let a3 = (a2 *. a) -. (b2 *. b) and b3 = (a2 *. b) +. (b2 *. a) in
      pr := a3 +. (3. *. ((c1r *. a) -. (ci *. b))) +. kr;
      pi := b3 +. (3. *. ((c1r *. b) +. (ci *. a))) +. ki;
      qr := (3. *. a2) +. (3. *. ((c2r *. a) -. (ci *. b))) +. kr +. 1.;
      qi := (3. *. b2) +. (3. *. ((c2r *. b) +. (ci *. a))) +. ki
    end;
    let pr = !pr and pi = !pi and qr = !qr and qi = !qi in
    let d = (qr *. qr) +. (qi *. qi) in
    let ur = ((pr *. qr) +. (pi *. qi)) /. d and ui = ((pi *. qr) -. (pr *. qi)) /. d in
    zr := (ur *. ur) -. (ui *. ui);
    zi := 2. *. ur *. ui;
    let z2 = (!zr *. !zr) +. (!zi *. !zi) in
    if z2 < !m2 then m2 := z2;
    let dr = !zr -. 1. in
    if z2 > 1e4 || (dr *. dr) +. (!zi *. !zi) < 1e-4 then (escaped := !n; n := it) else incr n
  done;
  if !escaped >= 0 then w.r.v <- exterior_shade f !escaped !zr !zi else w.r.v <- interior_shade f !zr !zi !m2


(* POV-Ray's ripples and waves patterns (pattern.cpp): the mean, over the
   sources, of the sine (cycloidal) of the distance d to the source
   (taken as 1 at the source) times the pattern's frequency plus its
   phase, 0.5 (1 + mean) for ripples; waves scales each d also by its
   source's frequency f and divides its sine by f, 0.2 (2.5 + mean). The
   frequency and phase apply again, as to any pattern, to the value. *)
let waves_into t (w : work) =
  let wv = waves () in
  let freq = t.frequency and phase = t.phase in
  let x = w.p.mx and y = w.p.my and z = w.p.mz in
  let ripples = match t.kind with Ripples -> true | _ -> false in
  let acc = ref 0. in
  for i = 0 to wv.count - 1 do
    let dx = x -. Float.Array.unsafe_get wv.src (3 * i)
    and dy = y -. Float.Array.unsafe_get wv.src ((3 * i) + 1)
    and dz = z -. Float.Array.unsafe_get wv.src ((3 * i) + 2) in
    let d = Float.sqrt ((dx *. dx) +. (dy *. dy) +. (dz *. dz)) in
    let d = if d = 0. then 1. else d in
    if ripples then acc := !acc +. cycloidal ((d *. freq) +. phase)
    else begin
      let f = Float.Array.unsafe_get wv.freq i in
      acc := !acc +. (cycloidal ((d *. freq *. f) +. phase) /. f)
    end
  done;
  let n = float_of_int wv.count in
  w.r.v <- (if ripples then 0.5 *. (1. +. (!acc /. n)) else 0.2 *. (2.5 +. (!acc /. n)))

(* The raw pattern at [w.p] into [w.r.v]: each case stores its value
   itself (a value joined from the cases would be boxed). *)
let raw_m t (w : work) =
  let kind = t.kind in
  let x = w.p.mx and y = w.p.my and z = w.p.mz in
  match kind with
  | Checker -> w.r.v <- checker3 x y z
  | Hexagon -> w.r.v <- hexagon3 x z
  | Brick { size; mortar } -> w.r.v <- brick3 size mortar x y z
  | Gradient v ->
      (* POV-Ray wraps a gradient above 1 itself (1.5 gives 0.5, 2 gives
         0, 1 stays 1), before the frequency step's wider wrap *)
      let g = (x *. v.x) +. (y *. v.y) +. (z *. v.z) in
      w.r.v <- (if g > 1. then Float.rem g 1. else g)
  | Radial ->
      (* POV-Ray's: 0.25 on the axis, else 0.25 + (atan2 x z + pi) / 2 pi,
         from 0.25 to 1.25 (what passes 1 is wrapped by the frequency
         step) *)
      w.r.v <-
        (if Float.abs x < 0.001 && Float.abs z < 0.001 then 0.25
         else 0.25 +. ((Float.atan2 x z +. Float.pi) /. two_pi))
  | Onion -> w.r.v <- Float.rem (Float.sqrt ((x *. x) +. (y *. y) +. (z *. z))) 1.
  | Planar ->
      let r = Float.abs y in
      w.r.v <- (if r > 1. then 0. else 1. -. r)
  | Spherical ->
      let r = Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) in
      w.r.v <- (if r > 1. then 0. else 1. -. r)
  | Boxed ->
      let r = Floats.fmax (Float.abs x) (Floats.fmax (Float.abs y) (Float.abs z)) in
      w.r.v <- (if r > 1. then 0. else 1. -. r)
  | Cylindrical ->
      let r = Float.sqrt ((x *. x) +. (z *. z)) in
      w.r.v <- (if r > 1. then 0. else 1. -. r)
  | Wood -> (
      (* POV-Ray's: with a classic turbulence, x and y each moved by the
         cycloidal of (the coordinate plus DTurbulence's) times the
         amount's component *)
      match t.turbulence with
      | None -> w.r.v <- Float.sqrt ((x *. x) +. (y *. y) +. 0.)
      | Some tb ->
          Noise.dturbulence ~octaves:tb.octaves ~omega:tb.omega ~lambda:tb.lambda w.p w.d;
          let px = cycloidal ((x +. w.d.mx) *. tb.amount.x) +. x
          and py = cycloidal ((y +. w.d.my) *. tb.amount.y) +. y in
          w.r.v <- Float.sqrt ((px *. px) +. (py *. py) +. 0.))
  | Marble -> (
      (* POV-Ray's: x plus the amount's x times the scalar Turbulence *)
      match t.turbulence with
      | None -> w.r.v <- x
      | Some tb ->
          w.r.v <-
            x
            +. tb.amount.x
               *. Noise.turbulence (generator t) ~octaves:tb.octaves ~omega:tb.omega ~lambda:tb.lambda x y z)
  | Leopard ->
      let s = (Float.sin x +. Float.sin y +. Float.sin z) /. 3. in
      w.r.v <- s *. s
  | Bozo | Spotted | Bumps -> w.r.v <- Noise.noise (generator t) x y z
  | Dents ->
      let n = Noise.noise (generator t) x y z in
      w.r.v <- n *. n *. n
  | Granite ->
      (* POV-Ray's: six octaves of |0.5 - noise| at 4 p (the original
         generator), of |1 - 2 noise| clipped to 0.5 (the others), each
         over its frequency *)
      let gen = generator t in
      let acc = ref 0. and freq = ref 1. in
      for _ = 0 to 5 do
        let f = !freq in
        let n = Noise.noise gen (x *. 4. *. f) (y *. 4. *. f) (z *. 4. *. f) in
        let v = if gen <= 1 then Float.abs (0.5 -. n) else Floats.fmin 0.5 (Float.abs (1. -. (2. *. n))) in
        acc := !acc +. (v /. f);
        freq := f *. 2.
      done;
      w.r.v <- !acc
  | Agate turb ->
      (* POV-Ray's: agate_turb (single precision) times the Turbulence of
         its classic turbulence's octaves, omega and lambda, in the
         cycloidal of 1.3 turb + 1.1 z, to the power 0.77 *)
      let tb = match t.turbulence with Some tb -> tb | None -> agate_turbulence in
      let tv = turb *. Noise.turbulence (generator t) ~octaves:tb.octaves ~omega:tb.omega ~lambda:tb.lambda x y z in
      let v = 0.5 *. (cycloidal ((1.3 *. tv) +. (1.1 *. z)) +. 1.) in
      w.r.v <- (if v < 0. then 0. else Float.pow (Floats.fmin 1. v) 0.77)
  | Ripples | Waves -> (* [waves_into]: they need the frequency and phase *) ()
  | Crackle c -> crackle_into c (generator t) w.p w.r
  | Wrinkles ->
      (* POV-Ray's: ten octaves of noise (the original generator's as it
         is, the others' 2 n - 0.5 clipped to [0, 1]), halved *)
      let gen = generator t in
      let n = Noise.noise gen x y z in
      let acc = ref (if gen <= 1 then n else Floats.fmin (Floats.fmax ((n *. 2.) -. 0.5) 0.) 1.) in
      let l = ref 2. and o = ref 0.5 in
      for _ = 1 to 9 do
        let li = !l in
        let n = Noise.noise gen (x *. li) (y *. li) (z *. li) in
        let n = if gen <= 1 then n else Floats.fmin (Floats.fmax ((n *. 2.) -. 0.5) 0.) 1. in
        acc := !acc +. (!o *. n);
        l := li *. 2.;
        o := !o *. 0.5
      done;
      w.r.v <- !acc /. 2.
  | Spiral1 arms -> w.r.v <- spiral3 arms w.r.v x y z
  | Spiral2 arms -> w.r.v <- tri (spiral3 arms w.r.v x y z) +. tri (Float.sqrt ((x *. x) +. (y *. y)))
  | Quilted { c0; c1 } -> w.r.v <- quilted3 c0 c1 x y z
  | Mandel f -> fractal_into f ~mandel:true ~cr:0. ~ci:0. w
  | Julia { cr; ci; fractal } -> fractal_into fractal ~mandel:false ~cr ~ci w
  | Magnet { formula; julia; cr; ci; fractal } -> magnet_into fractal formula ~julia ~cr ~ci w
  | Slope { dir; lo; hi; wdir; alt; alo; ahi; walt } ->
      (* POV-Ray's (measured): the normal's angle to the direction, 0.5 +
         asin(n . d) / pi, and the altitude p . a, each taken from [lo,
         hi] to [0, 1], weighed by the vectors' lengths *)
      (* the surface's world normal: POV-Ray does not turn it with the
         pattern's transformations (measured; the altitude's point is the
         pattern's) *)
      let n = Scratch.get normal_key in
      let c = (n.mx *. dir.x) +. (n.my *. dir.y) +. (n.mz *. dir.z) in
      let c = if c > 1. then 1. else if c < -1. then -1. else c in
      let s = (0.5 +. (Float.asin c /. Float.pi) -. lo) /. (hi -. lo) in
      let a = if walt = 0. then 0. else (((x *. alt.x) +. (y *. alt.y) +. (z *. alt.z)) -. alo) /. (ahi -. alo) in
      w.r.v <- ((wdir *. s) +. (walt *. a)) /. (wdir +. walt)
  | Tiling n -> Tiling.eval n w.p w.r
  | Density_file d -> w.r.v <- density3 d x y z
  | Image b -> w.r.v <- Bump_map.value b w.p
  | Object o -> w.r.v <- (if o.test w.p then 1. else 0.)
  | Material { w = iw; h = ih; once; numbers; count } ->
      let k = Bump_map.pixel ~w:iw ~h:ih ~once w.p in
      let n = if k < 0 then 0 else Char.code (Bytes.unsafe_get numbers k) in
      let n = if n > count then n mod count else n in
      w.r.v <- float_of_int (if n >= count then count - 1 else n)
  | Cells ->
      let i =
        Cells.index
          (int_of_float (Float.floor (x +. eps)))
          (int_of_float (Float.floor (y +. eps)))
          (int_of_float (Float.floor (z +. eps)))
      in
      w.r.v <- Float.Array.unsafe_get Cells.values i
  | Function f ->
      (* [w] is read before the code runs: the code may evaluate other
         patterns (through a pigment function), which may reuse [w] *)
      let s = Scratch.get f.frames in
      Array.unsafe_set s 0 x;
      Array.unsafe_set s 1 y;
      Array.unsafe_set s 2 z;
      f.run s;
      let v = Array.unsafe_get s f.result in
      (* POV-Ray: values above 1 taken mod 1, others left as they are *)
      w.r.v <- (if v > 1. then Float.rem v 1. else v)

let default_wave = function Wood | Marble | Spiral1 _ | Spiral2 _ -> Triangle | _ -> Ramp

(* the wave shaping of [v] into [w.r.v] (each case storing it), as
   POV-Ray writes them (its cycloidal for the sines) *)
let shape_into (w : work) wave v =
  match wave with
  | Ramp -> w.r.v <- v
  | Triangle -> w.r.v <- tri v
  | Sine -> w.r.v <- (1. +. cycloidal v) *. 0.5
  | Scallop -> w.r.v <- Float.abs (cycloidal (v *. 0.5))
  | Cubic -> w.r.v <- v *. v *. ((-2. *. v) +. 3.)
  | Poly e -> w.r.v <- Float.pow v e

(* POV-Ray's scalar Turbulence of a classic turbulence at [p], in the
   pattern's noise generator *)
let[@inline] scalar_turbulence t tb (p : Vec3.m) =
  Noise.turbulence (generator t) ~octaves:tb.octaves ~omega:tb.omega ~lambda:tb.lambda p.mx p.my p.mz

(* The pattern at [q] into [w.r.v], allocating nothing: turbulence warp,
   raw pattern, then frequency, phase and wave *)
(* One component of a point, by axis number (each case stores its own
   value: a value joined from the cases would be boxed). *)
let[@inline] component (p : Vec3.m) axis = if axis = 0 then p.mx else if axis = 1 then p.my else p.mz

let set_component (p : Vec3.m) axis v = if axis = 0 then p.mx <- v else if axis = 1 then p.my <- v else p.mz <- v

(* POV-Ray's turbulence warp: the point moved by DTurbulence times the
   amount, per axis *)
let add_turbulence tb (p : Vec3.m) (d : Vec3.m) =
  Noise.dturbulence ~octaves:tb.octaves ~omega:tb.omega ~lambda:tb.lambda p d;
  let a = tb.amount in
  Vec3.set p (p.mx +. (d.mx *. a.x)) (p.my +. (d.my *. a.y)) (p.mz +. (d.mz *. a.z))

(* The mapping warps' angle about y from +x, towards +z, in turns [0, 1)
   (acos as POV-Ray does: its values agree to the last bit) *)
let[@inline] turns x z len =
  if z = 0. then if x > 0. then 0. else 0.5
  else
    let a = Float.acos (x /. len) in
    (if z < 0. then two_pi -. a else a) /. two_pi

(* [len^e], e = 0 leaving the coordinates unscaled *)
let[@inline] dist_scale len e = if e = 0. then 1. else if e = 1. then len else Float.pow len e

(* A mapping warp's result (u, v, w) turned to its orientation [o]: u, v,
   w themselves along z; along x (z, v, -u); along y (u, -w, v); other
   directions mix these by their components, as POV-Ray does *)
let[@inline] orient_into (o : Vec3.t) (p : Vec3.m) u v w =
  if o.x = 0. && o.y = 0. && o.z = 1. then Vec3.set p u v w
  else
    Vec3.set p
      ((o.x *. w) +. (o.y *. u) +. (o.z *. u))
      ((o.x *. v) -. (o.y *. w) +. (o.z *. v))
      (-.(o.x *. u) +. (o.y *. v) +. (o.z *. w))

let apply_warp (wp : warp) (p : Vec3.m) (d : Vec3.m) =
  match wp.kind with
  | Planar_map { orient; offset } -> orient_into orient p p.mx p.my offset
  | Spherical_map { orient; dist_exp } ->
      let x = p.mx and y = p.my and z = p.mz in
      let dist = Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) in
      (* the centre stays where it is *)
      if dist > 0. then begin
        let x = x /. dist and y = y /. dist and z = z /. dist in
        let lat = 0.5 +. (Float.asin y /. Float.pi) in
        let len = Float.sqrt ((x *. x) +. (z *. z)) in
        let lon = if len = 0. then 0. else turns x z len in
        let k = dist_scale dist dist_exp in
        orient_into orient p (lon *. k) (lat *. k) dist
      end
  | Cylindrical_map { orient; dist_exp } ->
      let x = p.mx and z = p.mz in
      let len = Float.sqrt ((x *. x) +. (z *. z)) in
      if len > 0. then orient_into orient p (turns x z len *. dist_scale len dist_exp) p.my len
  | Toroidal_map { orient; dist_exp; major } ->
      let x = p.mx and y = p.my and z = p.mz in
      let len = Float.sqrt ((x *. x) +. (z *. z)) in
      if len > 0. then begin
        let around = turns x z len in
        (* the angle about the tube, from the inside of the ring, turning
           from -y towards +y through the outside *)
        let r = len -. major in
        let tube = Float.sqrt ((r *. r) +. (y *. y)) in
        let a = if tube = 0. then 0. else Float.acos (-.r /. tube) in
        let a = if y > 0. then two_pi -. a else a in
        let k = dist_scale tube dist_exp in
        orient_into orient p (around *. k) (a /. two_pi *. k) tube
      end
  | Turbulence tb -> add_turbulence tb p d
  | Repeat { axis; width; offset; flip } ->
      let x = component p axis in
      let cell = Float.floor (x /. width) in
      set_component p axis (x -. (cell *. width));
      if int_of_float cell land 1 = 1 then begin
        if flip.x < 0. then p.mx <- (if axis = 0 then width -. p.mx else -.p.mx);
        if flip.y < 0. then p.my <- (if axis = 1 then width -. p.my else -.p.my);
        if flip.z < 0. then p.mz <- (if axis = 2 then width -. p.mz else -.p.mz)
      end;
      Vec3.set p (p.mx +. (cell *. offset.x)) (p.my +. (cell *. offset.y)) (p.mz +. (cell *. offset.z))
  | Black_hole { center; radius; strength; falloff; inverse; repeat; jitter } ->
      (* POV-Ray's (warps.cpp), in its order of operations: a repeated
         hole's centre moved into the point's cell (the cell's numbers
         by floor), first by its turbulence: POV-Ray's warp random
         numbers (the pattern table, {!Cells.values}) from the slot the
         cell hashes to, times the turbulence; the point pushed from the
         centre (pulled when inverse) by strength ((radius - l) /
         radius)^falloff of its offset, at most all of it *)
      let x = p.mx and y = p.my and z = p.mz in
      let rep = repeat.x > 0. || repeat.y > 0. || repeat.z > 0. in
      let bx = if rep && repeat.x >= 1e-10 then int_of_float (Float.floor (x /. repeat.x)) else 0
      and by = if rep && repeat.y >= 1e-10 then int_of_float (Float.floor (y /. repeat.y)) else 0
      and bz = if rep && repeat.z >= 1e-10 then int_of_float (Float.floor (z /. repeat.z)) else 0 in
      let uncertain = rep && not (jitter.x = 0. && jitter.y = 0. && jitter.z = 0.) in
      let seed = if uncertain then Cells.index bx by bz else 0 in
      let cx = if uncertain then center.x +. (pick_rand seed *. jitter.x) else center.x
      and cy = if uncertain then center.y +. (pick_rand (seed + 1) *. jitter.y) else center.y
      and cz = if uncertain then center.z +. (pick_rand (seed + 2) *. jitter.z) else center.z in
      let cx = if rep then cx +. (repeat.x *. float_of_int bx) else cx
      and cy = if rep then cy +. (repeat.y *. float_of_int by) else cy
      and cz = if rep then cz +. (repeat.z *. float_of_int bz) else cz in
      let dx = x -. cx and dy = y -. cy and dz = z -. cz in
      let l = Float.sqrt ((dx *. dx) +. (dy *. dy) +. (dz *. dz)) in
      if l < radius then begin
        let k = Float.pow ((radius -. l) /. radius) falloff *. strength in
        let k = if k > 1. then 1. else k in
        let k = if inverse then -.k else k in
        Vec3.set p (x +. (dx *. k)) (y +. (dy *. k)) (z +. (dz *. k))
      end

let warped_m t (q : Vec3.m) (w : work) =
  Vec3.set w.p q.mx q.my q.mz;
  for i = Array.length t.warps - 1 downto 0 do
    let wp = Array.unsafe_get t.warps i in
    (* into the space the warp was written in (the transformations
       before it applied forward), warped, and back *)
    let id = Transform.is_identity wp.back in
    if not id then Transform.inv_point_m wp.into w.p w.p;
    apply_warp wp w.p w.d;
    if not id then Transform.inv_point_m wp.back w.p w.p
  done;
  match t.turbulence with
  | None -> ()
  | Some tb ->
      (* marble and wood read their turbulence themselves (POV-Ray's
         Warp_EPoint skips their classic turbulence) *)
      if own_turbulence t then Vec3.set w.e w.p.mx w.p.my w.p.mz else add_turbulence tb w.p w.d

let warp_in_place t (q : Vec3.m) (w : work) =
  if Array.length t.warps > 0 || t.turbulence <> None then begin
    warped_m t q w;
    Vec3.set q w.p.mx w.p.my w.p.mz
  end

let eval_warped t (w : work) =
  (* the spirals also add turbulence to their value, as POV-Ray 3.7 does
     (on top of the warp): read by [raw_m] from [w.r.v] *)
  (match (t.kind, t.turbulence) with
  | (Spiral1 _ | Spiral2 _), Some tb -> w.r.v <- tb.amount.x *. scalar_turbulence t tb w.p
  | _ -> w.r.v <- 0.);
  (match t.kind with Ripples | Waves -> waves_into t w | _ -> raw_m t w);
  if not (is_block t.kind) then begin
    if t.frequency <> 0. then begin
      (* POV-Ray's: mod 1.00001 (a value up to it is kept), a negative
         one less its floor *)
      let r = Float.rem ((w.r.v *. t.frequency) +. t.phase) 1.00001 in
      let v = if r < 0. then r -. Float.floor r else r *. 1. in
      shape_into w (match t.wave with Some wv -> wv | None -> default_wave t.kind) v
    end
    else begin
      (* POV-Ray: no wrapping (nor phase) at frequency 0, only a negative
         value taken mod 1 *)
      let r = w.r.v in
      let v = if r < 0. then r -. Float.floor r else r *. 1. in
      shape_into w (match t.wave with Some wv -> wv | None -> default_wave t.kind) v
    end
  end

let eval_m t (q : Vec3.m) (w : work) =
  warped_m t q w;
  eval_warped t w

(* The pattern at [point] taken into its space by [xform]'s inverse
   (inlined: the value is not boxed). [eval_m] reads its point before
   writing [w.p], which may therefore hold it. *)
let[@inline] eval_at t xform (point : Vec3.m) (w : work) =
  Transform.inv_point_m xform point w.p;
  eval_m t w.p w;
  w.r.v

(* Where [v] falls in a map's entries, sorted by value (n > 0): 0 when at
   or below the first, n past the last, else the i in 1..n-1 with the
   entries i-1 and i around it. *)
let around (entries : (float * 'a) array) v =
  let n = Array.length entries in
  if v <= fst entries.(0) then 0
  else begin
    let i = ref 1 in
    while !i < n && not (v < fst entries.(!i)) do
      incr i
    done;
    !i
  end

let value t (p : Vec3.t) =
  let w = work () and q = Vec3.m () in
  Vec3.load q p;
  eval_m t q w;
  w.r.v

(* [checker] at a point written in place: 0 or 1 *)
let checker_m (p : Vec3.m) =
  (int_of_float (Float.floor (p.mx +. eps))
  + int_of_float (Float.floor (p.my +. eps))
  + int_of_float (Float.floor (p.mz +. eps)))
  land 1
