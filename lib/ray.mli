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

(** A ray as mutable floats stored flat (origin, direction, and the far
    end of a walk along it): what the intersection code reads. One per domain is loaded from a {!t} per query (or written by a
    transform into object space), so queries allocate nothing per ray.
    Also used to hold a point (origin fields) for inside tests. *)
type scratch = {
  mutable ox : float;
  mutable oy : float;
  mutable oz : float;
  mutable dx : float;
  mutable dy : float;
  mutable dz : float;
  mutable far : float;
      (** where walks that read their range from the ray end ({!Bvh.iter_s},
          [Object.crossings_s], [Scene.occluders_s]); a float stored here,
          unlike one passed to a function, is not boxed *)
}

val scratch : unit -> scratch
val load : scratch -> t -> unit
(** [load s r] copies [r] into [s], with [far] infinite. *)

val set : scratch -> Vec3.m -> float -> float -> float -> unit
(** [set s o dx dy dz]: the origin [o] and the direction [(dx, dy, dz)]
    into [s] ([far] untouched). *)

val copy : scratch -> scratch -> unit
(** [copy src dst] *)

val of_ray : t -> scratch
(** A fresh scratch holding [r], [far] infinite (allocates: for tests and
    cold paths). *)
