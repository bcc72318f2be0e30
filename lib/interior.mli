(** POV-Ray's [interior]: what is inside a solid. *)

type t = {
  ior : float;
  fade_distance : float;
  fade_power : float;
  fade_color : Color.t;
}

val default : t
(** ior 1, no fade. *)

val fade_channel : t -> float -> float -> float
(** [fade_channel i c d]: the attenuation of a channel whose fade colour
    is [c] after travelling [d] inside (pov-facts.md 5.6); 1 when
    [fade_distance] is 0. [fade_power 0] gives a constant [c + (1 - c)/2]
    (povray 3.7 does so for what is seen through; its shadow rays do not
    fade then, see {!Whitted}). Inlined where it is used (the distance is
    not boxed). *)
