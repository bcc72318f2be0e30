(** Direct lighting in POV-Ray 3.7's classic model (pov-facts.md 5): the
    light each light source gives a point of a texture layer, with its
    shadow ({!Shadow}): diffuse with brilliance, back-side diffuse,
    Phong and Blinn (specular) highlights, metallic tints; an area light
    averages its shadow samples; with [area_illumination] that shadow
    scales what every sample of the grid gives as a point light, averaged
    (POV-Ray's rule). Ambient, emission, reflection and what passes
    through are {!Whitted}'s. *)

type opacity = { mutable alpha : float }
(** The layer's opacity: what its pigment does not filter or transmit
    (the factor of its diffuse light), stored flat so that passing it
    boxes nothing. *)

val single : float -> float
(** The nearest single-precision float (what POV-Ray keeps in its [SNGL]
    fields). *)

val irid_thickness : Finish.t -> Vec3.m -> float
(** [irid_thickness f p]: POV-Ray's film thickness of iridescence at the
    world point [p]: [f]'s thickness times 1 + (2 T - 1) [irid_turb],
    with T POV-Ray's Turbulence of [p] (5 octaves, omega 0.5, lambda 2,
    the scene's noise generator); both in single precision. *)

type shadows
(** The shadows found at one point, light by light, so that the layers of
    a texture and the textures of a texture map trace each shadow ray
    once (as POV-Ray does); with them the {!Shadow.walk} of the domain
    that made the record, which its shadow rays use. A record is used by
    the domain that made it only. *)

val shadows : unit -> shadows
(** An empty store. *)

val walk : shadows -> Shadow.walk
(** The shadow walk of the record's domain ({!Shadow.walk}), reached
    without a lookup. *)

val forget : shadows -> unit
(** Empty it: the next point shaded is another. *)

val set_highlights : shadows -> bool -> unit
(** Whether {!lights} draws Phong and specular highlights at the point
    (POV-Ray draws none for the surfaces radiosity's gather rays meet). *)

val lights :
  Scene.t -> shadows -> Light.t array -> Finish.t -> Pigment.out -> opacity -> Vec3.m -> Vec3.m -> Vec3.m ->
  Color.acc -> unit
(** [lights s c ls f pc a p n d out]: the diffuse light and highlights of
    every light of [ls] (the set of the surface shaded, one of
    [s.light_sets]: a light_group's lights light only its objects) at point [p] of normal [n] (facing the ray [d]),
    for the finish [f] and pigment [pc], added into [out]; the shadows
    kept in [c] are used (they must be [p]'s, for the same [ls]: {!forget} them when the
    point changes), those not kept are traced and kept. Allocates nothing
    unless a shadow ray crosses something transparent. *)

val photons :
  Scene.t -> Photon.map -> shadows -> Finish.t -> Pigment.out -> opacity -> Vec3.m -> Vec3.m -> Vec3.m -> Vec3.m ->
  Color.acc -> unit
(** [photons s m c f pc a p n n0 d out]: the light of the photons of map
    [m] gathered around [p] (normal [n], the layer's; [n0] the
    unperturbed one, both facing the ray [d]), as POV-Ray 3.7 adds it:
    each photon lights the point like a light from where it came, its
    flux divided by its cosine to [n0] (at least 0.1), through the
    finish's diffuse (or diffuse_back from behind) and, where [c] draws
    them, highlights; the sum over the area of the gather. Allocates
    nothing. *)
