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

(** {2 For lathes and others} *)

val spline_segment :
  spline -> (float * float) array -> int -> (float * float) * (float * float) * (float * float) * (float * float)
(** [spline_segment kind points k]: POV-Ray's coefficients (A, B, C, D,
    each an (x, y) pair) of the segment P(s) = ((A s + B) s + C) s + D,
    s in [0, 1], whose points start at index [k]. *)

val reach_of : spline -> int
(** How many points past [k] a segment reads (1, 2 or 3). *)

val extent : float -> float -> float -> float -> float * float
(** [extent a b c d]: the least and greatest values of the cubic
    [((a s + b) s + c) s + d] over [0, 1]. *)

val all_roots : Poly.scratch -> Float.Array.t -> int -> Float.Array.t -> float -> float -> int
(** [all_roots sc coefficients degree found lo hi]: the polynomial's roots
    in [[lo, hi)] in increasing order, into [found] (room for [degree]);
    their number. *)

val slab_misses : Ray.scratch -> float -> float -> float -> float -> float -> float -> bool
(** [slab_misses r ylo yhi near2 far2 tmin tmax]: whether the ray [r],
    not level, stays out of the solid between heights [ylo] and [yhi] and
    squared distances [near2] and [far2] from the y axis for t in (tmin,
    tmax): a lathe's or a sor's segment it need not solve for. *)

val keep_circle : Hit.t -> float -> Ray.scratch -> float -> float -> float -> bool
(** [keep_circle h tmin r rr id u]: a level ray's crossings of the circle
    of squared radius [rr] about the y axis, kept in [h] (part [id],
    parameter [u]) when in range; whether one was (lathes and sors). *)
