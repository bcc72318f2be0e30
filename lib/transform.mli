(** Affine transforms, stored with their inverse so that neither is ever
    recomputed per ray. Composition follows POV-Ray: each modifier applies
    after everything already attached to the object. *)

type t

val identity : t
val is_identity : t -> bool

val translate : Vec3.t -> t
val scale : Vec3.t -> t
(** Zero components must have been replaced by the caller (POV-Ray
    replaces them by 1 with a warning). *)

val rotate : Vec3.t -> t
(** [rotate <a,b,c>]: [a] degrees about x, then [b] about y, then [c] about
    z, with POV-Ray's (textbook) matrices: [rotate x*90] sends +y to +z. *)

val axis_rotate : Vec3.t -> float -> t
(** Rotation by the angle (degrees) about an axis through the origin, as
    POV-Ray's [vaxis_rotate]. *)

val of_pov_matrix : float array -> t option
(** POV-Ray's [matrix <a,b,c, d,e,f, g,h,i, j,k,l>] (row-vector form:
    x' = a x + d y + g z + j, ...). [None] when the matrix is singular. *)

val then_ : t -> t -> t
(** [then_ a b] applies [a] first, then [b]. *)

val inverse : t -> t

val opaque : t -> t
(** The same transformation, no longer taken for a plain [translate] or
    [scale] (a [transform { }] block or a declared transform: POV-Ray
    keeps those as transformations). *)

val as_translation : t -> Vec3.t option
(** The vector of a transformation made by [translate] keywords alone
    (its 3x3 part exactly the identity). *)

val is_turn : t -> bool
(** Made by one [rotate] keyword. *)

val as_scale : t -> Vec3.t option
(** The factors of a transformation made by [scale] keywords alone
    (diagonal, no translation). *)

val point : t -> Vec3.t -> Vec3.t
val vector : t -> Vec3.t -> Vec3.t
(** Apply to a direction (no translation). *)

val inv_point : t -> Vec3.t -> Vec3.t
val inv_vector : t -> Vec3.t -> Vec3.t

val normal : t -> Vec3.t -> Vec3.t
(** Transform an object-space normal by the inverse transpose; the result
    is not normalised. *)

val point_m : t -> Vec3.m -> Vec3.m -> unit
(** [point_m t p out]: {!point} in place (the same arithmetic; [p] and
    [out] may be the same vector). *)

val inv_point_m : t -> Vec3.m -> Vec3.m -> unit
(** [inv_point_m t p out]: {!inv_point} in place (the same arithmetic;
    [p] and [out] may be the same vector). *)

val normal_m : t -> Vec3.m -> unit
(** {!normal} in place. *)

val normal_inverse_m : t -> Vec3.m -> unit
(** [normal (inverse t)] in place. *)

val determinant : t -> float
val to_string : t -> string
