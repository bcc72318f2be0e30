(** POV-Ray's [superellipsoid { <e, n> }]: ((|x|^(2/e) + |y|^(2/e))^(e/n) +
    |z|^(2/n)) = 1 inside the box [-1, 1]^3. Found as POV-Ray finds it: the
    ray's stretch in the box cut where it crosses the nine planes that
    split the shape into smooth pieces, a root between samples of opposite
    sign homed in on by secant and bisection steps, a stretch without a
    sign change followed by Newton's method (POV-Ray's constants), so that
    silhouettes fall where POV-Ray's do. *)

type t

val make : float -> float -> t
(** [make e n]; requires both positive. *)

val value : t -> float -> float -> float -> float
(** The function, negative inside. *)

val inside : t -> float -> float -> float -> bool
val hit_s : t -> Ray.scratch -> float -> Hit.t -> bool
val normal_into : t -> Vec3.m -> Vec3.m -> unit
(** POV-Ray's normal at a point of the surface ([p] and [out] may be the
    same vector). *)

val bounds : Vec3.t * Vec3.t
