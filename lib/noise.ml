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

(* The same coefficients by a corner's index [i] in [0, 511] (the
   permutation read that gives its hash folded into the tables): [g1]
   holds at [3 i] the gradient of hash [perm.(i)]'s low four bits (the
   scalar noise's); [g9] at [9 i] that one too, at [9 i + 3] the gradient
   of its high four bits and at [9 i + 6] that of [perm.(perm.(i))]'s low
   four (the vector noise's three components). One index per corner, read
   at fixed offsets, where the hash, its bits and a second permutation
   read were taken for each gradient. (60 KB with the scaled permutations
   below; tables by the hash, 256 entries, would take 36 KB and 3 to 19
   more instructions a noise: docs/performance-notes.md, "Noise".) *)
let g1 =
  Float.Array.init (512 * 3) (fun k ->
      let h = perm.(k / 3) land 15 in
      Float.Array.get (match k mod 3 with 0 -> gx | 1 -> gy | _ -> gz) h)

let g9 =
  Float.Array.init (512 * 9) (fun k ->
      let h = perm.(k / 9) in
      let h = match k mod 9 / 3 with 0 -> h land 15 | 1 -> h lsr 4 | _ -> perm.(h) land 15 in
      Float.Array.get (match k mod 3 with 0 -> gx | 1 -> gy | _ -> gz) h)

(* the permutation times 3 and 9: the last read of a corner's index gives
   its offset in [g1] or [g9] *)
let perm3 = Array.map (fun h -> 3 * h) perm
let perm9 = Array.map (fun h -> 9 * h) perm

(* the gradient at offset [k] of table [t] dotted with (x, y, z) *)
let[@inline] dot t k x y z =
  (Float.Array.unsafe_get t k *. x) +. (Float.Array.unsafe_get t (k + 1) *. y) +. (Float.Array.unsafe_get t (k + 2) *. z)

(* floor as an int, without the C call Float.floor is (exact while |x|
   < 2^52, far beyond any coordinate a pattern reads) *)
let[@inline] ifloor x =
  let i = int_of_float x in
  if float_of_int i > x then i - 1 else i

(* every index is below 512: a cell's corner is at most 255, a table
   entry at most 255, and the sums at most 255 + 255 + 1 *)
let[@inline] p (t : int array) i = Array.unsafe_get t i

(* one component over the cell: the eight corners' gradients, at offsets
   [k0] to [k7] of table [t], blended by the fades [u], [v], [w] *)
let[@inline] cell_noise t u v w x y z x1 y1 z1 k0 k1 k2 k3 k4 k5 k6 k7 =
  lerp w
    (lerp v (lerp u (dot t k0 x y z) (dot t k1 x1 y z)) (lerp u (dot t k2 x y1 z) (dot t k3 x1 y1 z)))
    (lerp v (lerp u (dot t k4 x y z1) (dot t k5 x1 y z1)) (lerp u (dot t k6 x y1 z1) (dot t k7 x1 y1 z1)))

(* The lattice cell of (x, y, z), written once for both noises: the
   scalar noise there, and with [vector] (a constant where it is inlined,
   its tests folded away) the vector noise's second and third components
   into [out]. Inlined where it is used: a call would box its floats. *)
let[@inline] cell vector x y z (out : Vec3.m) =
  let ix = ifloor x and iy = ifloor y and iz = ifloor z in
  let xi = ix land 255 and yi = iy land 255 and zi = iz land 255 in
  let x = x -. float_of_int ix and y = y -. float_of_int iy and z = z -. float_of_int iz in
  let u = fade x and v = fade y and w = fade z in
  let a = p perm xi + yi and b = p perm (xi + 1) + yi in
  (* the four corners at z = zi, by their offsets in the table: the
     corners at zi + 1 are the next entries *)
  let pk = if vector then perm9 else perm3 and zs = if vector then 9 * zi else 3 * zi in
  let aa = p pk a + zs and ab = p pk (a + 1) + zs in
  let ba = p pk b + zs and bb = p pk (b + 1) + zs in
  let x1 = x -. 1. and y1 = y -. 1. and z1 = z -. 1. in
  let t = if vector then g9 else g1 in
  if vector then begin
    (* the second gradient by a corner hash's high four bits, the third by
       the permutation's entry at it *)
    out.my <- cell_noise t u v w x y z x1 y1 z1 (aa + 3) (ba + 3) (ab + 3) (bb + 3) (aa + 12) (ba + 12) (ab + 12) (bb + 12);
    out.mz <- cell_noise t u v w x y z x1 y1 z1 (aa + 6) (ba + 6) (ab + 6) (bb + 6) (aa + 15) (ba + 15) (ab + 15) (bb + 15)
  end;
  if vector then cell_noise t u v w x y z x1 y1 z1 aa ba ab bb (aa + 9) (ba + 9) (ab + 9) (bb + 9)
  else cell_noise t u v w x y z x1 y1 z1 aa ba ab bb (aa + 3) (ba + 3) (ab + 3) (bb + 3)

let dummy = Vec3.m ()
let[@inline] snoise3 x y z = cell false x y z dummy
let snoise (p : Vec3.t) = snoise3 p.x p.y p.z

(* in [0, 1] (comparisons, not Float.min and max, whose sign tests are C
   calls; the same values: 0.5 + 0.5 s is never -0 or nan) *)
let[@inline] noise3 x y z =
  let n = 0.5 +. (0.5 *. snoise3 x y z) in
  if n < 0. then 0. else if n > 1. then 1. else n

(* Three signed noises from one pass over the lattice cell of (x, y, z)
   (the displacement of one octave of [turbulence_m]): the first is
   [snoise3 x y z] to the bit; the second and third use gradients picked
   by other bits of the same corner hashes, so the cell's floor, fade and
   hashing are shared, as POV-Ray's DNoise shares them *)
let[@inline] dnoise3 x y z (out : Vec3.m) = out.mx <- cell true x y z out

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
