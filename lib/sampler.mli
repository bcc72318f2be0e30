(** Deterministic random numbers keyed by (seed, pixel, sample), so that an
    image never depends on the domain count or the tile order. A sampler
    is a small mutable counter owned by one pixel sample; never share one
    between domains. *)

type t

val create : seed:int -> pixel:int -> sample:int -> t
(** A fresh stream for one sample of one pixel ([pixel = y * width + x]). *)

val float : t -> float
(** Uniform in [[0, 1)], 53 random bits... at most 2^-53 below 1. *)

val hash : int -> int
(** The 62-bit mixing function behind the streams (a SplitMix-style
    finaliser on OCaml's native ints); exposed for tests. *)
