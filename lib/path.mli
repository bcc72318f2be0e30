(** Monte Carlo path tracing on the same scenes. This first version: the
    Lambertian part of a finish (albedo = pigment x diffuse), mirror
    reflection, emission, the background as an environment light, point
    lights sampled directly, Russian roulette after three bounces. *)

val li : Scene.t -> Sampler.t -> max_depth:int -> Ray.t -> Color.t
(** One radiance sample along a camera ray. *)

val pixel :
  Scene.t -> width:int -> height:int -> seed:int -> spp:int -> max_depth:int ->
  int -> int -> Color.t
(** Mean of [spp] samples of pixel [(x, y)], jittered inside the pixel
    (stratified on a grid when [spp] is a square). *)
