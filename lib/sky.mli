(** sky_sphere: pigments evaluated on the direction of rays that hit
    nothing, layered (the last written on top); where every layer is
    transparent the background shows through. *)

type t = {
  pigments : Pigment.t list;  (** the top (last written) first *)
  legacy : bool;
      (** POV-Ray 3.6's layering (scenes before [#version 3.7]): each
          layer weighed by the filter and transmit of those above as one
          number, not by their colour *)
}

val none : t

val is_empty : t -> bool

val transform : Transform.t -> t -> t
(** As POV-Ray: the pigments are evaluated at the direction moved like a
    point (so a translation shifts the sky). *)

val eval_into : t -> background:Color.t -> Vec3.m -> Color.acc -> unit
(** [eval_into s ~background dir out]: the colour seen along a unit
    direction, into [out], allocating nothing. *)
