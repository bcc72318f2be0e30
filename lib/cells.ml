(* POV-Ray's tables, rebuilt from the generators it makes them with. *)

let mask32 = 0xffff_ffff

(* POV-Ray's congruence (the C library's rand, on 32 bits): the next
   state, and the 15 bits 16 to 30 a draw gives *)
let lcg state = ((state * 1812433253) + 12345) land mask32
let[@inline] draw15 state = (state lsr 16) land 0x7fff

(* the permutation (POV-Ray's hash table, its noise's and its cells'):
   identity, then shuffled from the top with the congruence, seed 0 *)
let perm =
  let p = Array.init 4096 Fun.id in
  let state = ref 0 in
  for i = 4095 downto 0 do
    state := lcg !state;
    let j = draw15 !state mod 4096 in
    let t = p.(i) in
    p.(i) <- p.(j);
    p.(j) <- t
  done;
  p

(* MT19937 (Matsumoto and Nishimura's generator) from seed 5489: the
   first [n] outputs, each over 2^32 *)
let mersenne n =
  let mt = Array.make 624 0 in
  mt.(0) <- 5489;
  for i = 1 to 623 do
    let prev = mt.(i - 1) in
    mt.(i) <- ((1812433253 * (prev lxor (prev lsr 30))) + i) land mask32
  done;
  let next = ref 624 in
  let twist () =
    for k = 0 to 623 do
      let y = mt.(k) land 0x8000_0000 lor (mt.((k + 1) mod 624) land 0x7fff_ffff) in
      mt.(k) <- mt.((k + 397) mod 624) lxor (y lsr 1) lxor (if y land 1 = 1 then 0x9908_b0df else 0)
    done;
    next := 0
  in
  Float.Array.init n (fun _ ->
      if !next >= 624 then twist ();
      let y = mt.(!next) in
      incr next;
      let y = y lxor (y lsr 11) in
      let y = y lxor ((y lsl 7) land 0x9d2c_5680) in
      let y = y lxor ((y lsl 15) land 0xefc6_0000) in
      let y = (y lxor (y lsr 18)) land mask32 in
      float_of_int y /. 4294967296.)

(* 4098: crackle's points read the two after a cube's slot too *)
let values = mersenne 4098

let[@inline] index ix iy iz =
  let p i = Array.unsafe_get perm i in
  p (p (p (ix land 0xfff) lxor (iy land 0xfff)) lxor (iz land 0xfff))

let eps = 1e-10

let value x y z =
  let c v = int_of_float (Float.floor (v +. eps)) in
  Float.Array.get values (index (c x) (c y) (c z))
