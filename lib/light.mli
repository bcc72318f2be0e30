(** Light sources (POV-Ray 3.7 semantics, pov-facts.md 5.3). *)

type kind =
  | Point
  | Spot of { point_at : Vec3.t; radius : float; falloff : float; tightness : float }
      (** angles in degrees (half-angles from the axis) *)
  | Parallel of { point_at : Vec3.t }

type t = {
  position : Vec3.t;
  color : Color.t;
  kind : kind;
  fade_distance : float;
  fade_power : float;
  shadowless : bool;
}

val point : Vec3.t -> Color.t -> t

val attenuation : t -> Vec3.t -> float
(** Spot cone and distance fade factor for light arriving at a point. *)

val direction_to : t -> Vec3.t -> Vec3.t * float
(** Unit vector from the point towards the light, and the distance over
    which shadow rays must look (for parallel lights: to the plane through
    the light perpendicular to its direction). *)
