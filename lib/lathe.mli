(** POV-Ray's [lathe]: a curve of points (radius, height) in the xy plane
    (linear, quadratic, cubic or Bezier splines, POV-Ray's segment
    formulas) turned about the y axis. Along a ray a segment's surface is
    met where a polynomial of degree 6 in the curve's parameter vanishes
    ({!Prism.all_roots}); inside is where the half-line outward from a
    point's (radius, height) crosses the curve an odd number of times. *)

type t

val make : Prism.spline -> (float * float) array -> (t, string) result
val inside : t -> float -> float -> float -> bool
val hit_s : t -> Ray.scratch -> float -> Hit.t -> bool
val normal_into : t -> Vec3.m -> Hit.t -> Vec3.m -> unit
val bounds : t -> Vec3.t * Vec3.t
