(* Counter-based: number [dim] of a stream is hash(key + dim * golden),
   where key mixes seed, pixel and sample. Arithmetic wraps on 63-bit ints;
   we keep 62 bits so every step stays non-negative after masking. *)
type t = { mutable key : int; mutable n : int }

let mask = (1 lsl 62) - 1
let golden = 0x1E3779B97F4A7C15 land mask

let hash x =
  let x = x land mask in
  let x = (x lxor (x lsr 31)) * 0x3F58476D1CE4E5B9 land mask in
  let x = (x lxor (x lsr 29)) * 0x14D049BB133111EB land mask in
  (x lxor (x lsr 32)) land mask

let[@inline] key ~seed ~pixel ~sample = hash (hash (hash seed + pixel) + sample)
let create ~seed ~pixel ~sample = { key = key ~seed ~pixel ~sample; n = 0 }

let reset s ~seed ~pixel ~sample =
  s.key <- key ~seed ~pixel ~sample;
  s.n <- 0

(* top 53 of 62 bits *)
let[@inline] get s dim = float_of_int (hash (s.key + (dim * golden)) lsr 9) *. 0x1p-53

let float s =
  let v = get s s.n in
  s.n <- s.n + 1;
  v
