(** POV-Ray's [prism]: closed curves in the xz plane (linear, quadratic,
    cubic or Bezier splines, POV-Ray's segment formulas) swept along y
    from [height1] to [height2] ([linear_sweep]), or scaled by y from an
    apex at the origin ([conic_sweep]); inside is inside the curves (an
    odd number of crossings) between the heights. *)

type spline = Linear | Quadratic | Cubic | Bezier
type sweep = Linear_sweep | Conic_sweep

type t

val make : spline -> sweep -> float -> float -> ?open_:bool -> (float * float) array -> (t, string) result
(** [make spline sweep h1 h2 points]: the points (x, z) as POV-Ray reads
    them (control points included; a sub-curve ends where it comes back
    to its first point). [Error] says why the points make no prism. *)

val inside : t -> float -> float -> float -> bool
val hit_s : t -> Ray.scratch -> float -> Hit.t -> bool
val normal_into : t -> Vec3.m -> Hit.t -> Vec3.m -> unit
(** Outward unit normal at a point a hit found. *)

val bounds : t -> Vec3.t * Vec3.t
