(** POV-Ray 3.7's photon shooting: fills the scene's photon map
    ({!Photon}) for whitted mode's caustics.

    From every light that casts shadows, at every target (a top-level
    object whose [photons] block says [target]; a union's children each
    apart unless it says [split_union off]) for which the light's and the
    target's words turn refraction or reflection on: a grid of
    directions over the cone that holds the target's bounding sphere
    (its box's), rings [atan (spacing * multiplier / distance)] apart
    with jitter, so that photons land about [spacing] apart at the
    target ([count] sets the spacing from an estimate of how many that
    shoots, as POV-Ray does); rings stop past [autostop] of the cone once
    a ring misses the target. A photon starts with the light's colour
    (a spotlight's beam; an [area_light] light's grid split among its
    samples), is discarded if its first surface is not the target (a
    [pass_through] object is crossed), and after it meets every surface
    that [no_shadow] does not hide: stored where it lands (after its
    first surface, unless the surface says [collect off]), filtered by
    the pigments it crosses (filter and transmit; conserve_energy),
    faded by interiors, refracted and reflected where the surface's and
    the light's words allow it, down to the photons' trace level and
    ADC bailout. A stored photon's flux is its colour times the light's
    fade, spread^2 and the length of its way^2, so that the density of
    photons gives the light's intensity. *)

val shoot : ?par:Image.par -> Scene.t -> Photon.settings -> Photon.map * Photon.map option
(** The photon maps of a scene: the surfaces', and the media's when the
    settings ask for media photons ([media STEPS]) and some were left:
    after its first surface, over each stretch inside hollow interiors
    with media, a photon leaves up to STEPS photons, spaced [FACTOR]
    spreads apart at the distance travelled (jittered), each with the
    colour it came in with and a flux that makes their density the
    light's; its colour is dimmed by the stretch's mean extinction (a
    stretch too short for one sample leaves it without colour, as in
    POV-Ray). The rings of directions are shot in
    batches, with [par] on several domains, each ring with random
    numbers of its own and taken in order: the same photons every time,
    whatever the domains. *)

val prepare : ?par:Image.par -> Scene.t -> unit
(** Shoot the scene's photons once, when it has a [photons] block and
    they have not been shot yet. *)
