(** Shadow rays in POV-Ray 3.7's classic model: the light that reaches a
    point from a light, through what lies between. A surface crossed lets
    through (f*P + t) of its pigment (a texture's layers multiply, a
    texture map blends its textures'); an opaque one blocks (the walk
    stops there); an object with a fading interior and a fade power fades
    the light over the stretch that ends where the ray leaves it, the
    interiors the ray is in taken as POV-Ray takes them: at first the lit
    ray's ({!starts_in}), then each crossing leaves the crossed interior
    if the ray is in it, else enters it. An area light is the average of
    its samples (adaptive where it says so).

    The walk's state is a record per domain, reused from ray to ray:
    nothing is allocated unless the shadow ray crosses something
    transparent, and walks never nest (nothing here traces further). *)

type walk

val walk : unit -> walk
(** The calling domain's walk. *)

val starts_in : walk -> Interior.t list -> unit
(** [starts_in w l]: the shadow rays walked from here on start inside
    the interiors [l], those of the ray whose hit (or medium sample) they
    light, as POV-Ray copies them into its shadow ray. *)

val collects : walk -> bool -> unit
(** [collects w b]: whether the surface lit from here on gathers
    photons; then, as in POV-Ray, a photon target that refracts the
    light's photons blocks its shadow rays entirely (the light through
    it comes as photons). *)

val toward : walk -> Light.dir
(** The direction and distance to the light being shaded, which the
    caller sets ({!Light.direction_into}) before {!point} or {!light}. *)

val point : Scene.t -> walk -> Light.t -> Vec3.m -> unit
(** [point s w l p]: the light let through from the point light [l]
    (or one sample of it) whose direction is in [toward w] to [p], into
    [passed w]; the scene's atmospheric media dim it when [l] has
    media_attenuation on. A light with a projected_through object lets
    nothing through unless the ray meets the object before the light;
    then only what lies before that crossing casts shadows. A shadowless
    light is asked only that (callers ask a shadowless light without a
    projected_through object nothing). *)

val light : Scene.t -> walk -> Light.t -> Vec3.m -> unit
(** [light s w l p]: the same for light [l] at [p] (its direction in
    [toward w]); an area light averages its samples. *)

val passed : walk -> Color.acc
(** What the last {!point} or {!light} let through, per channel (0 where
    something opaque blocks, 1 where nothing is crossed). *)
