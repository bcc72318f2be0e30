(** POV-Ray's [interior]: what is inside a solid. *)

type t = {
  ior : float;
  fade_distance : float;
  fade_power : float;
  fade_color : Color.t;
}

val default : t
(** ior 1, no fade. *)

val fade : t -> float -> Color.t
(** Attenuation after travelling a distance inside (pov-facts.md 5.6);
    white when there is no fade. *)
