(* Perlin's improved-noise construction with camlray's own permutation. *)

let perm =
  let p = Array.init 256 Fun.id in
  (* fixed xorshift shuffle: the same table on every run *)
  let s = ref 0x2545F491 in
  let next () =
    let x = !s in
    let x = x lxor ((x lsl 13) land 0xFFFFFFFF) in
    let x = x lxor (x lsr 17) in
    let x = x lxor ((x lsl 5) land 0xFFFFFFFF) in
    s := x;
    x
  in
  for i = 255 downto 1 do
    let j = next () mod (i + 1) in
    let t = p.(i) in
    p.(i) <- p.(j);
    p.(j) <- t
  done;
  Array.init 512 (fun i -> p.(i land 255))

let[@inline] fade t = t *. t *. t *. ((t *. ((t *. 6.) -. 15.)) +. 10.)
let[@inline] lerp t a b = a +. (t *. (b -. a))

(* Perlin's 12 edge gradients (16 entries, 4 repeated), picked by the
   low 4 bits of a hash: +-u +- v with u, v two of x, y, z *)
let edge h x y z =
  let u = if h < 8 then x else y in
  let v = if h < 4 then y else if h = 12 || h = 14 then x else z in
  (if h land 1 = 0 then u else -.u) +. if h land 2 = 0 then v else -.v

(* the same as coefficient tables, read without a branch: at the higher
   octaves of a turbulence the hashes are random, and branches on them
   were mispredicted (a turbulence of 7 octaves, 21 noises: 2.4 to 2.6 us
   with branches, 0.70 to 0.72 us without; POV-Ray's advanced/benchmark
   at 96x96 on one domain: 30.3 s, 8.9 s; the same values to the bit,
   checked on 3 million points) *)
let gx = Float.Array.init 16 (fun h -> edge h 1. 0. 0.)
let gy = Float.Array.init 16 (fun h -> edge h 0. 1. 0.)
let gz = Float.Array.init 16 (fun h -> edge h 0. 0. 1.)

let[@inline] grad h x y z =
  let h = h land 15 in
  (Float.Array.unsafe_get gx h *. x) +. (Float.Array.unsafe_get gy h *. y) +. (Float.Array.unsafe_get gz h *. z)

(* floor as an int, without the C call Float.floor is (exact while |x|
   < 2^52, far beyond any coordinate a pattern reads) *)
let[@inline] ifloor x =
  let i = int_of_float x in
  if float_of_int i > x then i - 1 else i

(* every index is below 512: a cell's corner is at most 255, a table
   entry at most 255, and the sums at most 255 + 255 + 1 *)
let[@inline] p i = Array.unsafe_get perm i

(* one component over the cell: the eight corners' gradients [k0] to
   [k7] (hashes), blended by the fades [u], [v], [w] *)
let[@inline] cell_noise u v w x y z x1 y1 z1 k0 k1 k2 k3 k4 k5 k6 k7 =
  lerp w
    (lerp v (lerp u (grad k0 x y z) (grad k1 x1 y z)) (lerp u (grad k2 x y1 z) (grad k3 x1 y1 z)))
    (lerp v (lerp u (grad k4 x y z1) (grad k5 x1 y z1)) (lerp u (grad k6 x y1 z1) (grad k7 x1 y1 z1)))

(* inlined where it is used: a call would box its arguments and result *)
let[@inline] snoise3 x y z =
  let ix = ifloor x and iy = ifloor y and iz = ifloor z in
  let xi = ix land 255 and yi = iy land 255 and zi = iz land 255 in
  let x = x -. float_of_int ix and y = y -. float_of_int iy and z = z -. float_of_int iz in
  let u = fade x and v = fade y and w = fade z in
  let a = p xi + yi and b = p (xi + 1) + yi in
  let aa = p a + zi and ab = p (a + 1) + zi in
  let ba = p b + zi and bb = p (b + 1) + zi in
  let x1 = x -. 1. and y1 = y -. 1. and z1 = z -. 1. in
  cell_noise u v w x y z x1 y1 z1 (p aa) (p ba) (p ab) (p bb) (p (aa + 1)) (p (ba + 1)) (p (ab + 1)) (p (bb + 1))

let snoise (p : Vec3.t) = snoise3 p.x p.y p.z
let[@inline] noise3 x y z = Float.min 1. (Float.max 0. (0.5 +. (0.5 *. snoise3 x y z)))

(* Three signed noises from one pass over the lattice cell of (x, y, z)
   (the displacement of one octave of [turbulence_m]): the first is
   [snoise3 x y z] to the bit; the second and third use gradients picked
   by other bits of the same corner hashes, so the cell's floor, fade and
   hashing are shared, as POV-Ray's DNoise shares them (inlined where it
   is used: a call would box its floats) *)
let[@inline] dnoise3 x y z (out : Vec3.m) =
  let ix = ifloor x and iy = ifloor y and iz = ifloor z in
  let xi = ix land 255 and yi = iy land 255 and zi = iz land 255 in
  let x = x -. float_of_int ix and y = y -. float_of_int iy and z = z -. float_of_int iz in
  let u = fade x and v = fade y and w = fade z in
  let a = p xi + yi and b = p (xi + 1) + yi in
  let aa = p a + zi and ab = p (a + 1) + zi in
  let ba = p b + zi and bb = p (b + 1) + zi in
  let x1 = x -. 1. and y1 = y -. 1. and z1 = z -. 1. in
  let h0 = p aa and h1 = p ba and h2 = p ab and h3 = p bb in
  let h4 = p (aa + 1) and h5 = p (ba + 1) and h6 = p (ab + 1) and h7 = p (bb + 1) in
  (* the first gradient by a corner hash's low four bits (as [snoise3]),
     the second by its high four, the third by the table's entry at it *)
  Vec3.set out
    (cell_noise u v w x y z x1 y1 z1 h0 h1 h2 h3 h4 h5 h6 h7)
    (cell_noise u v w x y z x1 y1 z1 (h0 lsr 4) (h1 lsr 4) (h2 lsr 4) (h3 lsr 4) (h4 lsr 4) (h5 lsr 4)
       (h6 lsr 4) (h7 lsr 4))
    (cell_noise u v w x y z x1 y1 z1 (p h0) (p h1) (p h2) (p h3) (p h4) (p h5) (p h6) (p h7))

let turbulence_m ~octaves ~omega ~lambda (p : Vec3.m) (out : Vec3.m) =
  let px = p.mx and py = p.my and pz = p.mz in
  let ax = ref 0. and ay = ref 0. and az = ref 0. and amp = ref 1. and freq = ref 1. in
  for _ = 1 to Int.max 1 octaves do
    (* dnoise (freq p), the same sums as with vectors *)
    let f = !freq and a = !amp in
    dnoise3 (f *. px) (f *. py) (f *. pz) out;
    ax := !ax +. (a *. out.mx);
    ay := !ay +. (a *. out.my);
    az := !az +. (a *. out.mz);
    amp := !amp *. omega;
    freq := !freq *. lambda
  done;
  Vec3.set out !ax !ay !az

let[@inline] fractal3 octaves x y z =
  let acc = ref 0. and f = ref 1. in
  for _ = 1 to Int.max 1 octaves do
    let k = !f in
    acc := !acc +. (Float.abs (snoise3 (k *. x) (k *. y) (k *. z)) /. k);
    f := k *. 2.
  done;
  !acc
