(** POV-Ray 3.7's [rainbow]: a ring of colour about the antisolar
    direction, laid over what a ray in the open (inside no solid, or only
    hollow ones) brings back, before the atmosphere's media and fog.

    A ray whose direction makes the angle [a] with [direction] reads the
    colour map at [(a - angle + width / 2) / width] (when that is in [0,
    1)), jittered by up to [jitter] (camlray's jitter is a hash of the
    direction, the same on every run and for any number of domains; POV-Ray
    draws random numbers). The colour [c] is blended in by the distance
    [t] to what the ray met ({!Fog.missed} for the sky): [k = exp (-t /
    distance)], raised to at least [fade (1 - c.transmit) + c.transmit];
    the light [l] becomes [k l ((1 - f) + f c) + (1 - k) c] with [f = (1
    - k) c.filter]. Outside [arc_angle / 2] of [up] (measured about the
    direction) nothing is drawn; between [falloff_angle / 2] and it, [fade]
    rises smoothly from 0 to 1. Several rainbows drawn at one ray are
    averaged. *)

type t

val make :
  angle:float ->
  width:float ->
  distance:float ->
  jitter:float ->
  direction:Vec3.t ->
  up:Vec3.t ->
  arc:float ->
  falloff:float ->
  Pigment.t ->
  t
(** [angle] and [width] in degrees as written; [arc] and [falloff] as
    POV-Ray keeps them: half of [arc_angle] and [falloff_angle] in radians
    when written, else its unconverted default 180, which lets every
    direction in ([falloff] defaults to [arc] when only [arc_angle] is
    written). [direction] and [up] must be non-zero and not parallel, and
    [falloff <= arc] (the parser checks them). The pigment is read at
    [<index, 0, 0>]. *)

val drawn : t -> bool
(** POV-Ray skips a rainbow of zero distance or width. *)

val apply : t list -> Vec3.m -> float -> Color.acc -> unit
(** [apply rainbows dir t c]: the light [c] arriving from distance [t]
    along the unit direction [dir], with the rainbows laid over it.
    Allocates nothing. *)

val layer : t list -> Vec3.m -> float -> Color.acc -> Color.acc -> unit
(** [layer rainbows dir t a b]: {!apply} as the affine map it is, the
    light [c] becoming [a c + b] (per channel). Allocates nothing. *)
