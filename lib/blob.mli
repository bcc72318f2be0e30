(** POV-Ray's [blob]: the surface where a sum of fields reaches a
    threshold. Each component adds [strength (1 - (d / radius)^2)^2]
    within [radius] of itself ([d] the distance to its centre, or to its
    segment for a cylinder, whose ends are round); inside is where the sum
    exceeds the threshold. Along a ray the sum is a quartic in each
    stretch between the points where components start or stop counting:
    roots are found there by {!Poly.first_root_in}. *)

type component =
  | Sphere of { center : Vec3.t; radius : float; strength : float }
  | Cylinder of { a : Vec3.t; b : Vec3.t; radius : float; strength : float }

type t

val make : threshold:float -> component list -> t
(** Requires positive radii and distinct cylinder ends (the compiler
    checks them). *)

val field : t -> float -> float -> float -> float
(** The sum of the components' fields at a point. *)

val inside : t -> float -> float -> float -> bool
val hit_s : t -> Ray.scratch -> float -> Hit.t -> bool
val normal_into : t -> Vec3.m -> Vec3.m -> unit
(** [normal_into b p out]: the outward unit normal at [p] (against the
    field's gradient); [p] and [out] may be the same vector. *)

val bounds : t -> (Vec3.t * Vec3.t) option
(** The box of the components of positive strength; [None] when none
    has any (then there is no surface unless the threshold is not
    positive). *)
