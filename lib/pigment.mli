(** Pigments: the colour (with filter and transmit) of a surface point. *)

type t = Solid of Color.rgbft

val solid : Color.rgbft -> t
val black : t
(** POV-Ray's default pigment. *)

val eval : t -> Vec3.t -> Color.rgbft
(** The colour at a point in world space. *)
