(** Deterministic random numbers keyed by (seed, pixel, sample, dimension),
    so that an image never depends on the domain count or the tile order.
    A stream is a pure function of its key: [get s d] is the same number
    however many other numbers were drawn before, which lets an integrator
    give every random decision its own fixed dimension. *)

type t

val create : seed:int -> pixel:int -> sample:int -> t
(** A fresh stream for one sample of one pixel ([pixel = y * width + x]). *)

val reset : t -> seed:int -> pixel:int -> sample:int -> unit
(** Make [s] the stream {!create} would make (a sampler reused sample
    after sample, allocating nothing). *)

val get : t -> int -> float
(** [get s dim]: number [dim] (any non-negative int) of the stream,
    uniform in [[0, 1)] with 53 random bits. Pure: no state changes. *)

val float : t -> float
(** The next number of a sequential cursor over the same stream (starting
    at dimension 0): [get s 0], then [get s 1], ... Never share a sampler
    between domains. *)

val hash : int -> int
(** The 62-bit mixing function behind the streams (a SplitMix-style
    finaliser on OCaml's native ints); exposed for tests. *)
