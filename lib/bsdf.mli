(** Scattering by a {!Material.t}: evaluation, sampling and densities of
    its lobes. Conventions: [n] is the surface's unit normal on the side
    of [wo]; [wo] points away from the surface towards the viewer; [wi]
    points away from the surface towards where light comes from. Densities
    are per unit solid angle.

    Shading normals: given one ([?ns], or [bumped] lobes), the lobes are
    evaluated and sampled about it, while [n] decides the sides. A
    direction the lobes send to the wrong side of the surface (reflected
    below it, refracted above it) is mirrored about the surface's plane
    to the right side, and f and the density count both mirror images:
    nothing leaks through the surface, and f cos integrates over the
    hemisphere above [n] to what the lobes give over the whole sphere (a
    white Lambertian surface stays white, each of its samples weighing
    its albedo). [ns] should be a unit vector facing [n]'s side and [wo]
    ({!Material.face}). *)

val basis : Vec3.t -> Vec3.t * Vec3.t
(** Two unit tangents completing [n] to an orthonormal basis. *)

val cosine_hemisphere : Vec3.t -> float -> float -> Vec3.t
(** [cosine_hemisphere n u1 u2]: a direction with density cos / pi about [n]. *)

val eval : ?ns:Vec3.t -> Material.t -> n:Vec3.t -> wo:Vec3.t -> wi:Vec3.t -> Color.t
(** Sum of the non-delta lobes' f (without the cosine, which is taken
    about [n]; with [ns], 0 below the surface). *)

val pdf : ?ns:Vec3.t -> Material.t -> n:Vec3.t -> wo:Vec3.t -> wi:Vec3.t -> float
(** Density with which {!sample} picks [wi] through a non-delta lobe
    (with [ns], 0 below the surface). *)

val has_smooth : Material.t -> bool
(** Some lobe is not a delta (light sampling can help). *)

type sample = {
  wi : Vec3.t;
  weight : Color.t;  (** f cos / pdf, selection probabilities included *)
  pdf : float;  (** density of [wi] (0 for delta lobes) *)
  delta : bool;
}

val sample : ?ns:Vec3.t -> Material.t -> n:Vec3.t -> wo:Vec3.t -> float -> float -> float -> sample option
(** [sample m ~n ~wo u v w]: choose a lobe with [u] (in proportion to
    {!Material.weight}), a direction with [v], [w]. Non-delta lobes are
    combined (the weight is the sum of their f over the mixture density),
    which is unbiased; [None] when the material absorbs everything or the
    direction falls below the surface. *)

val fresnel : float -> float -> float
(** [fresnel eta cos_i]: exact unpolarised reflectance of a smooth
    dielectric boundary, [eta] = n_incident / n_transmitted; 1 under total
    internal reflection. *)

(** {1 In place}

    The same functions on a {!Material.lobes} with vectors in
    {!Vec3.m} and results written into the caller's records: what the
    path tracer calls at every vertex, allocating nothing. The forms above
    go through these. The lobes' shading normal is [m.ns] when
    [m.bumped]. *)

val eval_into : Material.lobes -> Vec3.m -> Vec3.m -> Vec3.m -> Color.acc -> unit
(** [eval_into m n wo wi out]: {!eval}. *)

val pdf_m : Material.lobes -> Vec3.m -> Vec3.m -> Vec3.m -> float
(** [pdf_m m n wo wi]: {!pdf} (inlined: the result is not boxed). *)

val has_smooth_m : Material.lobes -> bool

type pdf = { mutable pdf : float }

type sampled = { wi : Vec3.m; weight : Color.acc; p : pdf; mutable delta : bool }
(** A {!sample} written in place. *)

val sampled : unit -> sampled

val sample_into : Material.lobes -> Vec3.m -> Vec3.m -> float -> float -> float -> sampled -> bool
(** [sample_into m n wo u v w out]: {!sample} into [out]; [false] where it
    is [None] (inlined: [u], [v], [w] are not boxed). *)

val around_into : Vec3.m -> float -> float -> float -> float -> float -> unit
(** [around_into out x y z cos_t phi]: the direction at angle [acos cos_t]
    from the unit axis [(x, y, z)] and azimuth [phi] (what
    {!cosine_hemisphere} uses), into [out]. *)
