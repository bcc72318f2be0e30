(** Shapes in object space, POV-Ray's definitions. Intersection returns
    the nearest distance along the ray in [(tmin, tmax)], or [infinity]. *)

type t =
  | Sphere of { center : Vec3.t; radius : float }
  | Plane of { normal : Vec3.t; offset : float }
      (** unit [normal]; the surface is [normal . p = offset]; inside is
          [normal . p < offset] *)

val sphere : Vec3.t -> float -> t
val plane : Vec3.t -> float -> t
(** [plane n d]: POV-Ray's [plane { n, d }] ([n] is normalised). *)

val intersect : t -> Ray.t -> float -> float -> float
(** [intersect s ray tmin tmax] is the smallest root in [(tmin, tmax)], or
    [infinity]. *)

val normal : t -> Vec3.t -> Vec3.t
(** Outward unit normal at a point on the surface. *)

val inside : t -> Vec3.t -> bool
(** POV-Ray's inside test (used by CSG and the [inside] function). *)

val bounds : t -> (Vec3.t * Vec3.t) option
(** Axis-aligned bounds in object space; [None] for infinite shapes. *)
