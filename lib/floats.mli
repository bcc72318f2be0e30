(** Small helpers on unboxed float arrays for the hot path. *)

val sort_prefix : Float.Array.t -> int -> unit
(** [sort_prefix a n] sorts the first [n] entries of [a] in place,
    ascending, by insertion: the lists it serves are short (a ray's
    stretches in a blob, its crossings of a superellipsoid's planes, the
    ends of light cylinders). Allocates nothing. Raises [Invalid_argument]
    when [n] is negative or past the end of [a]. *)
