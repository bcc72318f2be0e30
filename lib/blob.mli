(** POV-Ray's [blob]: the surface where a sum of fields reaches a
    threshold. Each component adds [strength (1 - (d / radius)^2)^2]
    within [radius] of itself ([d] the distance to its centre, or to its
    segment for a cylinder, whose ends are round); inside is where the sum
    exceeds the threshold. A component may be placed by any affine
    transform (POV-Ray's component [scale], [rotate], [matrix] ...): its
    field is then taken at the point brought back into its own space, so a
    sphere stretched unevenly adds an ellipsoid's field. Along a ray the
    sum is a quartic in each stretch between the points where components
    start or stop counting (an affine map keeps a ray a line and its
    parameter): roots are found there by {!Poly.first_root_in}. *)

type component =
  | Sphere of { center : Vec3.t; radius : float; strength : float }
  | Cylinder of { a : Vec3.t; b : Vec3.t; radius : float; strength : float }
  | Placed of { shape : component; xform : Transform.t }
      (** [shape]'s field seen through [xform] (its own space to the
          blob's): the field at [p] is [shape]'s at [xform^-1 p] *)

val place : Transform.t -> component -> component
(** [place t c]: [c] placed by [t] after its own placement, if any. *)

type t

val make : threshold:float -> component list -> t
(** Requires positive radii, distinct cylinder ends and invertible
    placements (the compiler checks them). *)

val components : t -> int
(** How many components (in the order given to {!make}). *)

val field : t -> float -> float -> float -> float
(** The sum of the components' fields at a point. *)

val inside : t -> float -> float -> float -> bool

val hit_s : t -> Ray.scratch -> Ray.scratch -> float -> Hit.t -> bool
(** [hit_s b r world tmin h]: the nearest crossing of the ray [r] (in the
    blob's own space) past [tmin] and before [h.t]; [world] is the same
    ray in the world (the same parameter), read for its direction's
    length only. POV-Ray's depth tolerance (blob.cpp, 0.01) as POV-Ray
    applies it: no crossing nearer than 0.01 to the origin in the world
    is taken; and a component's stretch along the ray (a sphere's, an
    ellipsoid's, a cylinder's side; an end cap's only at its plane)
    whose end lies within 0.01 of the origin in the blob's own units has
    that end moved to 0: ending there, it counts nowhere; starting there,
    it counts from 0, where its field, a quartic along the ray, rises
    again outside the component (POV-Ray's shells around the components
    of a blob scaled up from a small one). *)

val normal_into : t -> Vec3.m -> Vec3.m -> unit
(** [normal_into b p out]: the outward unit normal at [p] (against the
    field's gradient; +x where no component reaches, as POV-Ray); [p] and
    [out] may be the same vector. *)

val weights : t -> Vec3.m -> Float.Array.t -> int array -> int
(** [weights b p ws ix]: POV-Ray's shares of the components in the
    texture at [p] (blob space): each component whose field is not zero
    there weighs the field's absolute value, the weights summing to 1.
    Their number [n] is returned; [ix.(j)] and [ws.(j)], [j < n], are the
    component (its index in {!make}'s list) and its share. [ws] and [ix]
    must have room for {!components} entries. Allocates nothing. *)

val bounds : t -> (Vec3.t * Vec3.t) option
(** The box of the components of positive strength; [None] when none
    has any (then there is no surface unless the threshold is not
    positive). *)
