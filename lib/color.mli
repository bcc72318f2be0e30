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
val luminance : t -> float
(** POV-Ray's grey value: 0.297 r + 0.589 g + 0.114 b. *)

val is_black : t -> bool
val pow : t -> float -> t
val to_string : t -> string

(** POV-Ray colours: rgb with filter and transmit. *)
type rgbft = { c : t; filter : float; transmit : float }

val opaque : t -> rgbft
val rgbft : float -> float -> float -> float -> float -> rgbft
