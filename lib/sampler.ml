(* Counter-based: the n-th number of a stream is hash(key + n * golden),
   where key mixes seed, pixel and sample. Arithmetic wraps on 63-bit ints;
   we keep 62 bits so every step stays non-negative after masking. *)
type t = { key : int; mutable n : int }

let mask = (1 lsl 62) - 1
let golden = 0x1E3779B97F4A7C15 land mask

let hash x =
  let x = x land mask in
  let x = (x lxor (x lsr 31)) * 0x3F58476D1CE4E5B9 land mask in
  let x = (x lxor (x lsr 29)) * 0x14D049BB133111EB land mask in
  (x lxor (x lsr 32)) land mask

let create ~seed ~pixel ~sample =
  let k = hash (hash (hash seed + pixel) + sample) in
  { key = k; n = 0 }

let float s =
  let v = hash (s.key + (s.n * golden)) in
  s.n <- s.n + 1;
  (* top 53 of 62 bits *)
  float_of_int (v lsr 9) *. 0x1p-53
