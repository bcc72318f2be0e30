(** What the Monte Carlo mode samples directly (next-event estimation):
    POV-Ray's light sources and emissive objects. The background is
    handled by {!Path} as an environment light.

    Scale: a point light of POV colour [c] is a delta light of intensity
    [pi c] with no distance fall-off (POV-Ray's rule; fade_distance and
    fade_power apply with POV's formula), so that a Lambertian surface of
    albedo [a] receives the radiance [a c cos theta], as in POV-Ray. *)

type t =
  | Delta of Light.t  (** point, spot or parallel light *)
  | Area of { light : Light.t; area : Light.area }
      (** POV's [area_light]: the rectangle [position + s axis1 + t axis2],
          [s, t] in [[-1/2, 1/2]] (the inscribed disc when [circular],
          turned to face the lit point when [orient]), a continuous version
          of POV's grid of samples: every point of it shines like a
          fall-off-free point light of the light's colour, to both sides,
          and the rectangle's total equals one such point light, so far
          away it lights as the point light at its centre does. Invisible,
          like POV's, so sampled only directly. *)
  | Sphere of { obj : Object.t; center : Vec3.t; radius : float }
      (** an emissive sphere (possibly moved, rotated, uniformly scaled),
          sampled inside the cone it subtends (uniformly by area from
          inside). *)

val of_scene : Scene.t -> t array
(** Every light source (those of light groups too: {!Path} lights a
    surface only by its light set), and every emissive object whose shape can be
    sampled (spheres under similarity transforms). Emissive objects of
    other shapes are still found by the paths (BSDF sampling only). *)

val emission : Object.t -> Vec3.t -> Color.t
(** Radiance emitted at a world point of an object: POV's
    (1 - filter - transmit) x pigment x finish emission of the top layer. *)

type sample = {
  wi : Vec3.t;  (** unit direction from the shading point to the light *)
  dist : float;  (** distance to the light along [wi] (shadow-ray length) *)
  value : Color.t;
      (** for [Delta] and [Area]: incident radiance times cos / density,
          i.e. the factor that multiplies f cos theta. [black] for
          [Sphere] (the caller traces a ray and reads the emission). *)
  pdf : float;  (** solid-angle density of [wi]; [0.] for [Delta]/[Area] (no MIS) *)
}

val sample : t -> Vec3.t -> float -> float -> sample option
(** [sample e p u v]: a direction towards the emitter from [p]. *)

val find_index : t array -> Object.t -> int
(** The position of the emissive sphere that is [o] in [es], or -1. *)

val pdf : t -> Vec3.t -> Vec3.t -> Vec3.t -> float
(** [pdf e p q nq]: the density with which {!sample} from [p] picks the
    direction towards [q] on the emitter (normal [nq]). *)

val find : t array -> Object.t -> t option
(** The emitter standing for an object, if it is sampled directly. *)

(** {1 In place} *)

type nums = { mutable dist : float; mutable pdf : float }
type sampled = {
  wi : Vec3.m;
  value : Color.acc;
  n : nums;
  pos : Vec3.m;  (** where the light is *)
  ld : Light.dir;  (** scratch *)
}
(** A {!sample} written in place. *)

val sampled : unit -> sampled

val sample_into : t -> Vec3.m -> float -> float -> sampled -> bool
(** [sample_into e p u v out]: {!sample} into [out], [false] for [None]
    (the same values, bit for bit). Allocates nothing. *)

val emission_into : Object.t -> Vec3.m -> Pigment.out -> Color.acc -> unit
(** [emission_into o p pig out]: {!emission} at a point held in place,
    into [out] ([pig]: scratch), the same values; allocates nothing. *)

val pdf_m : t -> Vec3.m -> Vec3.m -> Vec3.m -> float
(** {!pdf} of points held in place: the same value, nothing
    allocated. *)
