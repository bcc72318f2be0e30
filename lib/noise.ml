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

let[@inline] grad h x y z =
  let h = h land 15 in
  let u = if h < 8 then x else y in
  let v = if h < 4 then y else if h = 12 || h = 14 then x else z in
  (if h land 1 = 0 then u else -.u) +. if h land 2 = 0 then v else -.v

(* inlined where it is used: a call would box its arguments and result *)
let[@inline] snoise3 x y z =
  let fx = Float.floor x and fy = Float.floor y and fz = Float.floor z in
  let xi = int_of_float fx land 255 and yi = int_of_float fy land 255
  and zi = int_of_float fz land 255 in
  let x = x -. fx and y = y -. fy and z = z -. fz in
  let u = fade x and v = fade y and w = fade z in
  let a = perm.(xi) + yi and b = perm.(xi + 1) + yi in
  let aa = perm.(a) + zi and ab = perm.(a + 1) + zi in
  let ba = perm.(b) + zi and bb = perm.(b + 1) + zi in
  let x1 = x -. 1. and y1 = y -. 1. and z1 = z -. 1. in
  lerp w
    (lerp v
       (lerp u (grad perm.(aa) x y z) (grad perm.(ba) x1 y z))
       (lerp u (grad perm.(ab) x y1 z) (grad perm.(bb) x1 y1 z)))
    (lerp v
       (lerp u (grad perm.(aa + 1) x y z1) (grad perm.(ba + 1) x1 y z1))
       (lerp u (grad perm.(ab + 1) x y1 z1) (grad perm.(bb + 1) x1 y1 z1)))

let snoise (p : Vec3.t) = snoise3 p.x p.y p.z
let[@inline] noise3 x y z = Float.min 1. (Float.max 0. (0.5 +. (0.5 *. snoise3 x y z)))

let off1 = Vec3.make 31.416 17.21 (-9.73)
let off2 = Vec3.make (-23.1) 41.7 13.3

let turbulence_m ~octaves ~omega ~lambda (p : Vec3.m) (out : Vec3.m) =
  let ax = ref 0. and ay = ref 0. and az = ref 0. and amp = ref 1. and freq = ref 1. in
  for _ = 1 to Int.max 1 octaves do
    (* dnoise (freq p), the same sums as with vectors *)
    let f = !freq and a = !amp in
    let x = f *. p.mx and y = f *. p.my and z = f *. p.mz in
    ax := !ax +. (a *. snoise3 x y z);
    ay := !ay +. (a *. snoise3 (x +. off1.x) (y +. off1.y) (z +. off1.z));
    az := !az +. (a *. snoise3 (x +. off2.x) (y +. off2.y) (z +. off2.z));
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
