(** sky_sphere: pigments evaluated on the direction of rays that hit
    nothing, layered (the last written on top); where every layer is
    transparent the background shows through. *)

type t = { pigments : Pigment.t list  (** the top (last written) first *) }

val none : t

val is_empty : t -> bool

val transform : Transform.t -> t -> t
(** As POV-Ray: the pigments are evaluated at the direction moved like a
    point (so a translation shifts the sky). *)

val eval : t -> background:Color.t -> Vec3.t -> Color.t
(** Colour seen along a unit direction. *)

val eval_into : t -> background:Color.t -> Vec3.m -> Color.acc -> unit
(** {!eval} for a direction written in place, into a sum (the same
    arithmetic), allocating nothing. *)
