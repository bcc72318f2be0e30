(** A mutable scratch record for intersection queries. All fields are
    floats, so OCaml stores them flat and updating them never allocates.
    A query searches the open interval [(tmin, t)], reading [t] as its upper
    bound, and on success overwrites every field. *)

type t = {
  mutable t : float;  (** the hit distance (on entry: the upper bound) *)
  mutable u : float;  (** surface parameters (barycentric u for triangles) *)
  mutable v : float;  (** barycentric v for triangles *)
  mutable id : float;
      (** which part was hit: box face, cylinder cap, triangle index
          (an integer stored as a float; never negative in a shape's
          record: the scene marks the spheres it keeps flat with
          negative ids) *)
  mutable floor : float;
      (** a further lower bound: crossings at or before it are not
          accepted ([neg_infinity] but while a walk over an object's
          crossings, which raises it past each crossing it passes, is
          under way: a bound passed to the query instead would be boxed) *)
}

val create : float -> t
(** [create tmax]: a fresh record with upper bound [tmax]. *)

val copy_into : t -> t -> unit
(** [copy_into src dst]. *)

val keep : t -> float -> float -> float -> float -> bool
(** [keep h tmin t id u]: when [t] lies in [(tmin, h.t)], record it (with
    the part [id] and the surface parameter [u]) and say so. Inlined
    where it is used (its floats are not boxed). *)
