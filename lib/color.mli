(** Linear RGB colours and radiance, and POV-Ray's five-channel colours
    (red, green, blue, filter, transmit). *)

type t = { r : float; g : float; b : float }

val make : float -> float -> float -> t
val gray : float -> t
val black : t
val white : t
val add : t -> t -> t
val mul : t -> t -> t
val scale : float -> t -> t
val madd : t -> float -> t -> t
(** [madd a k b] is [a + k b]. *)

val max_channel : t -> float
val grey : float -> float -> float -> float
(** [grey r g b]: {!luminance} of the channels, inlined. *)

val luminance : t -> float
(** POV-Ray's grey value: 0.297 r + 0.589 g + 0.114 b. *)

val is_black : t -> bool
val pow : t -> float -> t
val to_string : t -> string

(** A colour summed in place: mutable and flat, so that updating it
    allocates nothing (the shading loops keep running sums in these). *)
type acc = { mutable ar : float; mutable ag : float; mutable ab : float }

val acc : float -> acc
(** [acc v]: a new sum holding grey [v]. *)

val acc_set : acc -> float -> float -> float -> unit

val acc_store : Float.Array.t -> int -> acc -> unit
(** [acc_store fa i a]: the sum into floats [3 i] to [3 i + 2] of [fa]. *)

val acc_load : Float.Array.t -> int -> acc -> unit
(** [acc_load fa i a]: floats [3 i] to [3 i + 2] of [fa] into the sum. *)

val of_acc : acc -> t
val acc_max : acc -> float
val acc_is_black : acc -> bool
val acc_luminance : acc -> float

(** POV-Ray colours: rgb with filter and transmit. *)
type rgbft = { c : t; filter : float; transmit : float }

val opaque : t -> rgbft
val rgbft : float -> float -> float -> float -> float -> rgbft
