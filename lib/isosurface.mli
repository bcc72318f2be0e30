(** POV-Ray's [isosurface { function { f } ... }]: the surface where
    [f (x, y, z) = threshold] inside a container (a box or a sphere);
    inside where [f <= threshold] within the container. Found as POV-Ray
    finds it: the ray's stretch in the container is cut in halves, a half
    dropped when its two end values show (with [max_gradient] as a bound
    on the function's slope) that it cannot cross the threshold, down to
    stretches of at most [accuracy]; the hit is the end of the first such
    stretch whose end is inside (so hits lie up to [accuracy] inside, as
    POV-Ray's do). The ray's direction is taken to unit length in the object's
    own space, so [accuracy] and [max_gradient] are in the function's
    units whatever the object's transform. When the function is below the
    threshold where the search starts, the search looks for where it
    rises above it (POV-Ray's sign flip); a search starting at the ray's
    origin on the surface (the function within [max_gradient *
    accuracy] of the threshold) looks past a crossing closer than 5
    accuracies. Unless
    [open], the container's surface shows where the function is inside
    at it. The normal is the function's gradient by forward differences
    of step [accuracy] ([+x] where it is zero), on a sphere container's
    surface too, as POV-Ray's; a box container's faces have their own. *)

type container =
  | Box of Vec3.t * Vec3.t  (** two opposite corners *)
  | Sphere of Vec3.t * float  (** centre, radius *)

type fn
(** A compiled function of x, y, z (the parser's function compiler gives
    one; lib cannot depend on it). *)

val fn : slots:int -> result:int -> (float array -> unit) -> fn
(** [fn ~slots ~result run]: [run s] reads x, y, z from [s.(0)], [s.(1)],
    [s.(2)], works in slots below [slots] and leaves the value in
    [s.(result)]; it must allocate nothing for the hit test to allocate
    nothing. Each domain gets its own slots. *)

val fn_of_closure : (float -> float -> float -> float) -> fn
(** A function given as an OCaml closure (tests). *)

type t

val make :
  fn:fn ->
  container:container ->
  threshold:float ->
  accuracy:float ->
  max_gradient:float ->
  open_:bool ->
  max_trace:int ->
  t
(** [max_trace] is how many crossings one search finds at most
    ([max_int] for POV-Ray's [all_intersections]). Requires [accuracy]
    and [max_gradient] positive, [max_trace] at least 1. *)

val value : t -> float -> float -> float -> float
(** [f (x, y, z) - threshold]. *)

val inside : t -> float -> float -> float -> bool
val hit_s : t -> Ray.scratch -> float -> Hit.t -> bool

val normal_into : t -> Vec3.m -> Hit.t -> Vec3.m -> unit
(** The outward normal at a hit ([p] and [out] may be the same vector). *)

val bounds : t -> Vec3.t * Vec3.t
(** The container's bounds. *)

