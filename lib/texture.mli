(** Textures: pigment and finish (and, later, normal perturbation), single
    or layered. *)

type layer = { pigment : Pigment.t; finish : Finish.t }

type t = layer list
(** Layers from the top (last written) down; never empty. *)

val plain : Pigment.t -> Finish.t -> t
val default : t
(** Black pigment, default finish: what POV-Ray gives an object with no
    texture. *)
