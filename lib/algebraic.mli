(** Algebraic surfaces, POV-Ray's [poly], [cubic], [quartic] and [quadric]:
    the points where a polynomial in x, y, z of some order is zero, the
    inside where it is negative. *)

type t

val max_order : int
(** 15, as POV-Ray's [poly]. *)

val terms : int -> int
(** The number of coefficients of an order: 10, 20, 35 for 2, 3, 4. *)

val make : ?inside_below:float -> int -> float array -> t
(** [make order coefficients] in POV-Ray's order: the power of x falling
    first, then y's, then z's (for order 4: x^4, x^3 y, x^3 z, x^3,
    x^2 y^2, ..., z, 1). [inside_below] (default POV-Ray's [poly]
    tolerance, 1e-4): a point is inside where the polynomial is below it.
    Raises [Invalid_argument] for an order outside 1 .. {!max_order} or a
    wrong number of coefficients. *)

val order : t -> int

val quadric : t -> float array option
(** For a surface of order 2 without mixed terms, [[|a; b; c; d; e; f;
    g|]]: the inside is [a x^2 + b y^2 + c z^2 + d x + e y + f z + g < 0]
    (the inside's threshold taken into [g]). *)

val eval : t -> float -> float -> float -> float
(** The polynomial's value at a point. *)

val inside : t -> float -> float -> float -> bool

val gradient_into : t -> float -> float -> float -> Vec3.m -> unit
(** The gradient at a point (not normalised; zero at singular points). *)

val along : t -> float -> float -> float -> float -> float -> float -> Float.Array.t
(** [along s qx qy qz nx ny nz]: the polynomial along the line [q + t n],
    its coefficients ascending in t (degree {!order}), as {!hit_s} makes
    them (from the point of the ray's line nearest the origin, and its
    unit direction). For tests; allocates. *)

val hit_s : t -> Ray.scratch -> float -> Hit.t -> bool
(** The nearest crossing in [(tmin, h.t)] past [h.floor] (and POV-Ray's
    depth tolerance: 1e-4 along the unit direction from the origin),
    recorded in [h]. Allocates nothing. *)

val first_hit : t -> float -> float -> float -> float -> float -> float -> float -> float
(** [first_hit s ox oy oz dx dy dz tmin]: the smallest distance [t >
    tmin] (in units of the direction) where the ray meets the surface, at
    least POV-Ray's depth tolerance (1e-4 along the unit direction) from
    its origin; [infinity] if none ({!hit_s} for tests and tools). *)
