(** Media along a ray in whitted mode (POV-Ray 3.7's sampling, see
    {!Media.pieces}): what a stretch of ray inside solids with media lets
    through, and the light they emit and scatter toward the eye. *)

val apply : Scene.t -> Vec3.m -> Vec3.m -> float -> Interior.t list -> Color.acc -> unit
(** [apply s o d t inside c]: [c], the light arriving at distance [t] (in
    units of [d]) along the ray from [o], as seen from [o] through the
    media of the interiors [inside]: dimmed by
    [exp (-integral of extinction)], plus emission and the single
    scattering of each light (with its shadow, media_interaction lights
    only). Nothing happens when no interior has media, or [t] is
    infinite. *)
