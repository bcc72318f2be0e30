(** Textures: a stack of layers, the top layer first (POV-Ray's layered
    textures: several [texture { }] on one object, the last one written on
    top). *)

type layer = { pigment : Pigment.t; normal : Normal.t option; finish : Finish.t }
type t = layer list

val layer : Pigment.t -> Finish.t -> layer
(** No normal perturbation. *)

val plain : Pigment.t -> Finish.t -> t
val default : t
(** Black pigment, default finish: what objects without a texture get. *)

val transform_layer : Transform.t -> layer -> layer
val transform : Transform.t -> t -> t
(** Move the patterns of a texture (a texture written before an object
    transform moves with the object). *)
