(** Per-domain scratch records: found without [Domain.DLS], and kept off
    the cache lines of shared data. See the implementation for the
    measurements behind both. *)

type 'a key

val key : (unit -> 'a) -> 'a key
(** A value per domain, made by the function on a domain's first [get]. *)

val get : 'a key -> 'a
(** The calling domain's value. A domain that ends leaves its value to
    the next domain given its index (scratch is never in use by two
    domains at once). *)

val set_apart : unit -> unit
(** Make the calling domain's scratch now, padded on both sides: call it
    from the main domain before the scene is built. *)
