(** Media along a ray in whitted mode (POV-Ray 3.7's sampling): what a
    stretch of ray inside solids with media lets through, and the light
    they emit and scatter toward the eye. The stretch is cut where it
    enters and leaves spotlights' cones ({!Lit}), into POV-Ray's sampling
    intervals (as many as the medium's [intervals], or as the lit and
    unlit stretches, shared among them by its [ratio]), each sampled by
    the medium's method ({!Media.pieces}). *)

val apply : Scene.t -> Vec3.m -> Vec3.m -> float -> starts:Interior.t list -> Interior.t list -> Color.acc -> unit
(** [apply s o d t ~starts inside c]: [c], the light arriving at distance [t] (in
    units of [d]) along the ray from [o], as seen from [o] through the
    media of the interiors [inside]: dimmed by
    [exp (-integral of extinction)], plus emission and the single
    scattering of each light (with its shadow, media_interaction lights
    only, and not shadowless ones, which POV-Ray's media leave out; each
    within its own lit stretch; the shadow rays start in the interiors
    [starts], the ray's own, whether [inside] is they or the scene's
    atmosphere). The settings are those of
    the medium with the most intervals. Nothing happens when no interior has media, or [t] is
    infinite. *)
