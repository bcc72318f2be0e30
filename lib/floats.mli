(** Small helpers on unboxed float arrays for the hot path. *)

val sort_prefix : Float.Array.t -> int -> unit
(** [sort_prefix a n] sorts the first [n] entries of [a] in place,
    ascending, by insertion: the lists it serves are short (a ray's
    stretches in a blob, its crossings of a superellipsoid's planes, the
    ends of light cylinders). Allocates nothing. Raises [Invalid_argument]
    when [n] is negative or past the end of [a]. *)

val order_prefix : Float.Array.t -> int -> int array -> unit
(** [order_prefix a n ord]: [ord.(0 .. n-1)] the indices [0 .. n-1] of
    [a] in ascending order of their values, by insertion, equal values in
    index order; [a] is left as it is (a ray's recorded crossings, whose
    other records are kept beside them by index). Allocates nothing.
    Raises [Invalid_argument] when [n] is negative or past the end of [a]
    or [ord]. *)

val single : float -> float
(** [x] rounded to single precision (as POV-Ray keeps its [SNGL] fields),
    as a double. *)

val fmin : float -> float -> float
(** The lesser of two numbers by one comparison, inlined: [Float.min] is
    a call that orders NaN and -0 by the C library's [signbit], which a
    hot loop over numbers that are neither need not pay. *)

val fmax : float -> float -> float
(** The greater, likewise. *)
