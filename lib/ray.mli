(** Rays: origin and direction (not necessarily unit length; intersection
    distances are in units of the direction's length). *)

type t = { origin : Vec3.t; dir : Vec3.t }

val make : Vec3.t -> Vec3.t -> t
val at : t -> float -> Vec3.t

val epsilon : float
(** The smallest hit distance accepted for rays leaving a surface
    (secondary rays), in units of a unit direction. The one place where
    self-intersection is handled. *)

val shadow_epsilon : float
(** POV-Ray ignores shadow-ray hits closer than this (1e-3). *)
