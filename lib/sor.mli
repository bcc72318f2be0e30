(** POV-Ray's [sor] (surface of revolution): points (radius, height) with
    rising heights; between each inner pair the squared radius is a cubic
    in the height (Hermite: the squares at the two points, and slopes
    [2 r_i (r_(i+1) - r_(i-1)) / (y_(i+1) - y_(i-1))] from their
    neighbours; the first and last points only steer the slopes), turned
    about the y axis; closed by discs at the first and last inner points
    unless open (measured with POV-Ray's [trace()]). *)

type t

val make : open_:bool -> (float * float) array -> (t, string) result
(** At least 4 points, the heights of the curve's points rising, radii
    not negative. *)

val radius2 : t -> float -> float
(** The squared radius at a height within the curve (for tests). *)

val inside : t -> float -> float -> float -> bool
val hit_s : t -> Ray.scratch -> float -> Hit.t -> bool
val normal_into : t -> Vec3.m -> Hit.t -> Vec3.m -> unit
val bounds : t -> Vec3.t * Vec3.t
