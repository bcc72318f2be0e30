(* POV-Ray 3.7's noise, the noise of every pattern, function and
   turbulence: Perlin's lattice noise as POV-Ray computes it (Skinner's version): a
   value and a gradient at each lattice corner, read from a table of 267
   pseudo-random numbers by a hash of the corner, blended by the cubic
   s-curve. What makes it POV-Ray's are its tables, rebuilt here from
   how they were made:
   - the hash: 0 .. 4095 shuffled by the C library's linear congruence
     (x <- 1812433253 x + 12345 on 32 bits, bits 16 to 30 drawn), seed 0,
     from the last entry down (Cells.perm: cells and crackle hash by the
     same table); doubled to 8192 so that sums of two 12-bit indices
     need no mask;
   - the numbers: entry i is the CRC-16 (polynomial 0xA001, reflected, as
     in ARC) of the 24 bytes of the vector (0.12345 i, 0.12345 i,
     0.12345 i) as big-endian doubles, scaled to [-1, 1] by 2 / 65535 and
     rounded to 6 significant digits (the table was computed once on a
     big-endian machine and printed with %g; POV-Ray 3.7 keeps those
     printed values).
   Values checked against POV-Ray 3.7's f_noise3d in test_noise. *)

let hash_table = Array.append Cells.perm Cells.perm

(* made once: remade per entry it cost every start 7 M instructions *)
let crc_table =
  Array.init 256 (fun i ->
      let c = ref i in
      for _ = 1 to 8 do
        c := if !c land 1 = 1 then (!c lsr 1) lxor 0xA001 else !c lsr 1
      done;
      !c)

let crc16 bytes =
  let table = crc_table in
  Bytes.fold_left (fun c b -> (c lsr 8) lxor table.((c lxor Char.code b) land 0xFF)) 0 bytes

let r_entry i =
  let v = float_of_int i *. 0.12345 in
  let b = Bytes.create 24 in
  for k = 0 to 2 do
    Bytes.set_int64_be b (8 * k) (Int64.bits_of_float v)
  done;
  let r = (float_of_int (crc16 b) *. (2.0 /. 65535.0)) -. 1.0 in
  float_of_string (Printf.sprintf "%g" r)

(* entry k at 2k, half of it at 2k + 1: a corner's value and its three
   gradient components are then at fixed offsets 1, 2, 4, 6 from 2k *)
let r_table =
  let t = Float.Array.make (267 * 2) 0. in
  for i = 0 to 266 do
    let v = r_entry i in
    Float.Array.set t (2 * i) v;
    Float.Array.set t ((2 * i) + 1) (v *. 0.5)
  done;
  t

(* entry [k]'s half and the three entries after it, the four numbers a
   corner reads, in an array of their own: read at constant offsets, each
   is one load (offsets from a computed index take an addition each) *)
let corners =
  Array.init 264 (fun k ->
      Float.Array.of_list (List.map (Float.Array.get r_table) [ (2 * k) + 1; (2 * k) + 2; (2 * k) + 4; (2 * k) + 6 ]))

let[@inline] hash (i : int) = Array.unsafe_get hash_table i
let[@inline] hash2 a b = hash (hash a lxor b)
let[@inline] r_index h z = hash (h lxor z) land 0xFF

(* a corner's contribution, weight [s], from entry [k] on *)
let[@inline] incrsum k s x y z =
  let q = Array.unsafe_get corners k in
  s
  *. (Float.Array.unsafe_get q 0 +. (Float.Array.unsafe_get q 1 *. x) +. (Float.Array.unsafe_get q 2 *. y)
     +. (Float.Array.unsafe_get q 3 *. z))

let[@inline] scurve a = a *. a *. (3.0 -. (2.0 *. a))

(* the lattice coordinate below [x] as POV-Ray takes it: truncation, with
   negative values moved down by 1 - 1e-10 first *)
let[@inline] lattice x = if x >= 0. then int_of_float x else int_of_float (x -. (1. -. 1e-10))

(* POV-Ray's noise generators: 1 its original noise, 2 the same with its
   range stretched to [0, 1] (3.7's default), 3 Perlin's solid noise *)
type generator = int

(* The lattice cell of (x, y, z), set up once for both noises: with
   [vector] false the sum over its eight corners (Noise's, before the
   generator's scaling), with [vector] true DNoise's three sums into [out]
   (0 returned), each in POV-Ray's order of the corners. Inlined where it
   is used, [vector] a constant there: a call would box its floats. *)
let[@inline] lattice_cell vector x y z (out : Vec3.m) =
  let tmp = lattice x in
  let ix = (tmp + 10000) land 0xFFF and x_ix = x -. float_of_int tmp in
  let tmp = lattice y in
  let iy = (tmp + 10000) land 0xFFF and y_iy = y -. float_of_int tmp in
  let tmp = lattice z in
  let iz = (tmp + 10000) land 0xFFF and z_iz = z -. float_of_int tmp in
  let x_jx = x_ix -. 1. and y_jy = y_iy -. 1. and z_jz = z_iz -. 1. in
  let sx = scurve x_ix and sy = scurve y_iy and sz = scurve z_iz in
  let tx = 1. -. sx and ty = 1. -. sy and tz = 1. -. sz in
  let txty = tx *. ty and sxty = sx *. ty and txsy = tx *. sy and sxsy = sx *. sy in
  let h00 = hash2 ix iy and h10 = hash2 (ix + 1) iy in
  let h01 = hash2 ix (iy + 1) and h11 = hash2 (ix + 1) (iy + 1) in
  let iz1 = iz + 1 in
  if vector then begin
    (* POV-Ray's order of the corners, the components from the table's
       entries 4 and 8 further on *)
    let k = r_index h00 iz and s = txty *. tz in
    let rx = incrsum k s x_ix y_iy z_iz and ry = incrsum (k + 4) s x_ix y_iy z_iz and rz = incrsum (k + 8) s x_ix y_iy z_iz in
    let k = r_index h10 iz and s = sxty *. tz in
    let rx = rx +. incrsum k s x_jx y_iy z_iz and ry = ry +. incrsum (k + 4) s x_jx y_iy z_iz
    and rz = rz +. incrsum (k + 8) s x_jx y_iy z_iz in
    let k = r_index h11 iz and s = sxsy *. tz in
    let rx = rx +. incrsum k s x_jx y_jy z_iz and ry = ry +. incrsum (k + 4) s x_jx y_jy z_iz
    and rz = rz +. incrsum (k + 8) s x_jx y_jy z_iz in
    let k = r_index h01 iz and s = txsy *. tz in
    let rx = rx +. incrsum k s x_ix y_jy z_iz and ry = ry +. incrsum (k + 4) s x_ix y_jy z_iz
    and rz = rz +. incrsum (k + 8) s x_ix y_jy z_iz in
    let k = r_index h01 iz1 and s = txsy *. sz in
    let rx = rx +. incrsum k s x_ix y_jy z_jz and ry = ry +. incrsum (k + 4) s x_ix y_jy z_jz
    and rz = rz +. incrsum (k + 8) s x_ix y_jy z_jz in
    let k = r_index h11 iz1 and s = sxsy *. sz in
    let rx = rx +. incrsum k s x_jx y_jy z_jz and ry = ry +. incrsum (k + 4) s x_jx y_jy z_jz
    and rz = rz +. incrsum (k + 8) s x_jx y_jy z_jz in
    let k = r_index h10 iz1 and s = sxty *. sz in
    let rx = rx +. incrsum k s x_jx y_iy z_jz and ry = ry +. incrsum (k + 4) s x_jx y_iy z_jz
    and rz = rz +. incrsum (k + 8) s x_jx y_iy z_jz in
    let k = r_index h00 iz1 and s = txty *. sz in
    out.mx <- rx +. incrsum k s x_ix y_iy z_jz;
    out.my <- ry +. incrsum (k + 4) s x_ix y_iy z_jz;
    out.mz <- rz +. incrsum (k + 8) s x_ix y_iy z_jz;
    0.
  end
  else
    let sum = incrsum (r_index h00 iz) (txty *. tz) x_ix y_iy z_iz in
    let sum = sum +. incrsum (r_index h10 iz) (sxty *. tz) x_jx y_iy z_iz in
    let sum = sum +. incrsum (r_index h01 iz) (txsy *. tz) x_ix y_jy z_iz in
    let sum = sum +. incrsum (r_index h11 iz) (sxsy *. tz) x_jx y_jy z_iz in
    let sum = sum +. incrsum (r_index h00 iz1) (txty *. sz) x_ix y_iy z_jz in
    let sum = sum +. incrsum (r_index h10 iz1) (sxty *. sz) x_jx y_iy z_jz in
    let sum = sum +. incrsum (r_index h01 iz1) (txsy *. sz) x_ix y_jy z_jz in
    sum +. incrsum (r_index h11 iz1) (sxsy *. sz) x_jx y_jy z_jz

(* where the scalar sum's cell writes nothing *)
let unused = Vec3.m ()

(* the sum over the eight corners, before the generator's scaling *)
let[@inline] lattice_sum x y z = lattice_cell false x y z unused

(* ---- Perlin's solid noise (generator 3), its tables made as POV-Ray
   makes them: 2048 gradients drawn in the cube [-1, 1) (steps of 1/2048)
   by the same congruence from seed 1, kept when inside the unit ball
   and not too short, normalised; then a permutation of 0 .. 2047 by
   swaps at every second entry from the top; both doubled. The
   permutation's entry 2048 starts at 0 (a static array in POV-Ray) and
   takes part in the first swap. *)
let entries = 2048

let solid_grad, solid_perm =
  let g = Float.Array.make (3 * 2 * (entries + 1)) 0. in
  let p = Array.make (2 * (entries + 1)) 0 in
  let s = ref 1 in
  let comp () =
    s := Cells.lcg !s;
    float_of_int ((Cells.draw15 !s mod (entries lsl 1)) - entries) /. float_of_int entries
  in
  for i = 0 to entries - 1 do
    let rec pick () =
      let x = comp () in
      let y = comp () in
      let z = comp () in
      let l = (x *. x) +. (y *. y) +. (z *. z) in
      if l > 1.0 || l < 1.0e-5 then pick () else (x, y, z, 1.0 /. sqrt l)
    in
    (* scaled by the reciprocal of the length, as POV-Ray 3.7.0 does (a
       division instead is one unit in the last place off at times) *)
    let x, y, z, r = pick () in
    Float.Array.set g (3 * i) (x *. r);
    Float.Array.set g ((3 * i) + 1) (y *. r);
    Float.Array.set g ((3 * i) + 2) (z *. r)
  done;
  for i = 0 to entries - 1 do
    p.(i) <- i
  done;
  let i = ref entries in
  while !i > 0 do
    let k = p.(!i) in
    s := Cells.lcg !s;
    let j = Cells.draw15 !s mod entries in
    p.(!i) <- p.(j);
    p.(j) <- k;
    i := !i - 2
  done;
  for i = 0 to entries + 1 do
    p.(entries + i) <- p.(i);
    for c = 0 to 2 do
      Float.Array.set g ((3 * (entries + i)) + c) (Float.Array.get g ((3 * i) + c))
    done
  done;
  (g, p)

let rollover = 10000000.023157213

let[@inline] sg k = Float.Array.unsafe_get solid_grad k
let[@inline] sp i = Array.unsafe_get solid_perm i
let[@inline] at b x y z = (x *. sg (3 * b)) +. (y *. sg ((3 * b) + 1)) +. (z *. sg ((3 * b) + 2))
let[@inline] plerp t a b = a +. (t *. (b -. a))

let[@inline] solid x y z =
  let tx = x +. rollover in
  let it = int_of_float (Float.floor tx) in
  let bx0 = it land (entries - 1) in
  let bx1 = (bx0 + 1) land (entries - 1) and rx0 = tx -. float_of_int it in
  let ty = y +. rollover in
  let it = int_of_float (Float.floor ty) in
  let by0 = it land (entries - 1) in
  let by1 = (by0 + 1) land (entries - 1) and ry0 = ty -. float_of_int it in
  let tz = z +. rollover in
  let it = int_of_float (Float.floor tz) in
  let bz0 = it land (entries - 1) in
  let bz1 = (bz0 + 1) land (entries - 1) and rz0 = tz -. float_of_int it in
  let rx1 = rx0 -. 1. and ry1 = ry0 -. 1. and rz1 = rz0 -. 1. in
  let i = sp bx0 and j = sp bx1 in
  let b00 = sp (i + by0) and b10 = sp (j + by0) and b01 = sp (i + by1) and b11 = sp (j + by1) in
  let sx = scurve rx0 and sy = scurve ry0 and sz = scurve rz0 in
  let a = plerp sx (at (b00 + bz0) rx0 ry0 rz0) (at (b10 + bz0) rx1 ry0 rz0) in
  let b = plerp sx (at (b01 + bz0) rx0 ry1 rz0) (at (b11 + bz0) rx1 ry1 rz0) in
  let c = plerp sy a b in
  let a = plerp sx (at (b00 + bz1) rx0 ry0 rz1) (at (b10 + bz1) rx1 ry0 rz1) in
  let b = plerp sx (at (b01 + bz1) rx0 ry1 rz1) (at (b11 + bz1) rx1 ry1 rz1) in
  let d = plerp sy a b in
  plerp sz c d

(* [noise gen x y z]: POV-Ray's Noise, in [0, 1] *)
let[@inline] noise (gen : generator) x y z =
  let v =
    if gen = 3 then 0.5 *. ((1.59 *. solid x y z) +. 0.985)
    else
      let sum = lattice_sum x y z in
      if gen = 2 then (sum +. 1.05242) *. 0.48985582 else sum +. 0.5
  in
  if v < 0. then 0. else if v > 1. then 1. else v

(* [dnoise x y z out]: POV-Ray's DNoise (the same for every generator) *)
let[@inline] dnoise x y z (out : Vec3.m) = ignore (lattice_cell true x y z out)

(* one octave of POV-Ray's Turbulence: the original generator's noise as
   it is, the others' stretched to 2 n - 0.5 *)
let[@inline] octave gen x y z = if gen <= 1 then noise gen x y z else (2.0 *. noise gen x y z) -. 0.5

(* [turbulence gen ~octaves ~omega ~lambda x y z]: POV-Ray's Turbulence
   (its first octave clamped to [0, 1] for generators 2 and 3) *)
let[@inline] turbulence gen ~octaves ~omega ~lambda x y z =
  let v = octave gen x y z in
  let v = if gen <= 1 then v else if v < 0. then 0. else if v > 1. then 1. else v in
  let value = ref v and l = ref lambda and o = ref omega in
  for i = 2 to octaves do
    let li = !l in
    value := !value +. (!o *. octave gen (x *. li) (y *. li) (z *. li));
    if i < octaves then begin
      l := li *. lambda;
      o := !o *. omega
    end
  done;
  !value

(* [dturbulence ~octaves ~omega ~lambda p out]: POV-Ray's DTurbulence *)
let dturbulence ~octaves ~omega ~lambda (p : Vec3.m) (out : Vec3.m) =
  let x = p.mx and y = p.my and z = p.mz in
  dnoise x y z out;
  let rx = ref out.mx and ry = ref out.my and rz = ref out.mz and l = ref lambda and o = ref omega in
  for i = 2 to octaves do
    let li = !l and oi = !o in
    dnoise (x *. li) (y *. li) (z *. li) out;
    rx := !rx +. (oi *. out.mx);
    ry := !ry +. (oi *. out.my);
    rz := !rz +. (oi *. out.mz);
    if i < octaves then begin
      l := li *. lambda;
      o := oi *. omega
    end
  done;
  Vec3.set out !rx !ry !rz
