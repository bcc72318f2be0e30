(** POV-Ray 3.7's classic lighting model (pov-facts.md section 5):
    ambient and emission, diffuse with brilliance and back-side diffuse,
    Phong and Blinn highlights, metallic, layered textures, normal
    perturbation, shadows through filtering and transmitting surfaces
    (with interior fade), area lights, reflection (constant, falloff,
    Fresnel, exponent, metallic), refraction with nested interiors and
    total internal reflection, trace level and ADC bailout, background and
    sky_sphere. Lights and highlights are {!Direct}'s, shadow rays
    {!Shadow}'s, the relative index across nested interiors
    {!Interior.relative_ior}.

    Rules found by cross-rendering with POV-Ray 3.7 (beyond pov-facts.md):
    - interior fade multiplies what comes through the far side of a medium
      (the transmitted or totally reflected ray at the surface where the
      ray leaves, by the distance just travelled inside), not that far
      surface's own shading;
    - shadow rays fade over every stretch inside a fading object,
      including the stretch from a lit point that is itself inside;
    - a transparent sky_sphere lets the background through (filter and
      transmit as for surfaces). *)

val trace : Scene.t -> Ray.t -> Color.t
(** Radiance (linear working space) along a camera ray (trace level 1). *)

val sample : Scene.t -> width:int -> height:int -> float -> float -> Color.t
(** [sample s ~width ~height px py]: the camera ray through the image
    point [(px, py)] (pixel [(i, j)] spans [[i, i+1) x [j, j+1)], row 0 at
    the top). *)

val sample_into : Scene.t -> width:int -> height:int -> float -> float -> Color.acc -> unit
(** {!sample} written into a sum the caller owns (overwritten). *)

val pixel : Scene.t -> width:int -> height:int -> int -> int -> Color.t
(** The colour of pixel [(x, y)]: one ray through the pixel centre. *)

val pixel_into : Scene.t -> width:int -> height:int -> int -> int -> Color.acc -> unit
(** {!pixel} written into a sum the caller owns (overwritten); after
    {!prepare} of a scene with radiosity at that size, the colour its
    final pass found (the same ray's, traced then). A camera
    ray that crosses nothing transparent allocates nothing but what
    patterns other than a plain checker and sky spheres need. *)

val prepare :
  ?par:Image.par -> ?batch:int -> ?progress:(done_:int -> total:int -> unit) -> Scene.t -> width:int -> height:int -> unit
(** For a scene with radiosity, POV-Ray's pretrace and the gathers of
    its final pass: fills the scene's irradiance cache from coarse
    passes of camera rays, then through every pixel's centre (coarse
    pixels first), each ray after the ones before it; the centres'
    colours are the picture's ({!pixel_into} at that size takes them),
    and the cache serves the rest of the render (anti-aliasing's
    samples). With [par] (several domains), [batch] rays (128) at a time
    are traced ahead at once and then taken in turn: the same cache and
    colours as on one domain. [progress] is told how many of its rays
    are done, from the calling domain. Without a [prepare], every point gathers
    anew (the same picture in the mean, noisier and much slower).
    Nothing for other scenes. *)

val start_media : Scene.t -> Vec3.m -> Interior.t list
(** The interiors of every object holding a point (a camera ray's
    origin), innermost first as POV-Ray starts its camera rays (the last
    object in the scene first). Cached per domain, scene and origin; a
    new origin held by the same objects gives the same list. *)
