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

(** Records by nesting depth, kept per domain (in a key's value): a ray's
    frame and the frames of the rays it traces, nested maps' colours. *)
type 'a levels

val levels : ?initial:int -> (unit -> 'a) -> 'a levels
(** [initial] (default 4) made at once, the others when first asked for. *)

val level : 'a levels -> int -> 'a
(** The record at a depth (0 the outermost). *)

val push : 'a levels -> 'a
(** The record at the current depth, which then goes one deeper. *)

val pop : 'a levels -> unit
(** Back one level ([push] and [pop] pair up). *)

val reset : 'a levels -> unit
(** Back to depth 0. *)
