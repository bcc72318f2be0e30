(** Monte Carlo path tracing on the same scenes: an unbiased estimator of
    the radiance reaching the camera. POV-Ray textures become physical
    materials ({!Material}), their [normal]s shading normals ({!Bsdf});
    light sources and emissive spheres are sampled
    directly ({!Emitter}) and, for emitters that paths can also hit
    (emissive objects, the background), light sampling and BSDF sampling
    are combined by multiple importance sampling with the power heuristic.
    Russian roulette after three bounces; [max_depth] caps the number of
    bounces. [ambient] is ignored.

    Fog and media: a path keeps the interiors it runs in; each of its
    stretches is seen through the fogs (POV-Ray's blend, {!Fog.blend_into})
    and the media there ({!Medium}: emission, absorption, and scattering
    as a participating medium, a vertex in the medium lit by next-event
    estimation and continued by the phase function). Shadow rays are
    dimmed by the media and fogs they cross (by POV-Ray's light flags
    toward its lights). A path passing straight through a clear surface
    (ior 1) keeps the light-sampling weight of the vertex before it. *)

type t
(** A scene prepared for path tracing (its emitters listed once). *)

val prepare : ?nee:bool -> ?extra:Emitter.t list -> Scene.t -> t
(** [nee] (default [true]): next-event estimation. With [false], light is
    found only by BSDF sampling (delta lights are then never seen): the
    two estimators must agree on scenes without delta lights. [extra]:
    emitters not (yet) expressible in the scene language. *)

val li : t -> Sampler.t -> max_depth:int -> Ray.t -> Color.t
(** One radiance sample along a camera ray ([ray.dir] a unit vector).
    Random dimensions 0-3 of the sampler are left to the caller (pixel and
    lens). *)

val pixel_into :
  t -> width:int -> height:int -> seed:int -> spp:int -> max_depth:int -> int -> int -> Color.acc -> unit
(** {!pixel} written into a sum the caller owns: a sample walks its path
    in per-domain records, allocating nothing in the common case (solid
    pigments, point lights and the background, shapes of any kind, no
    focal blur). *)

val pixel :
  t -> width:int -> height:int -> seed:int -> spp:int -> max_depth:int -> int -> int -> Color.t
(** Mean of [spp] samples of pixel [(x, y)], jittered inside the pixel
    (stratified on a grid when [spp] is a square), each from its own
    sampler keyed by (seed, pixel, sample): the result does not depend on
    which domain computes it. *)
