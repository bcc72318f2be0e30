(** POV-Ray's [interior]: what is inside a solid. *)

type t = {
  ior : float;
  fade_distance : float;
  fade_power : float;
  fade_color : Color.t;
  hollow : bool;
      (** the object's [hollow]: a ray inside only hollow solids is in the
          open, where fog is seen *)
  caustics : float;
      (** POV-Ray's faked caustics, 45 x the scene's [caustics] value (0:
          none): a shadow ray through the surface carries (1 + |cos|^caustics)
          times the light it lets through, cos between the ray and the
          surface's normal (whitted mode) *)
  media : Media.t list;  (** its [media { }], in source order (whitted mode) *)
  mutable slot : int;
      (** a number for the caches of {!beyond}, given by {!number} when a
          scene is made (0 before); two interiors may share one, which
          only slows the caches. Not read by anything else. *)
}

val default : t
(** ior 1, no fade, not hollow. *)

val fade_channel : t -> float -> float -> float
(** [fade_channel i c d]: the attenuation of a channel whose fade colour
    is [c] after travelling [d] inside (pov-facts.md 5.6); 1 when
    [fade_distance] is 0. [fade_power 0] gives a constant [c + (1 - c)/2]
    (povray 3.7 does so for what is seen through; its shadow rays do not
    fade then, see {!Whitted}). Inlined where it is used (the distance is
    not boxed). *)

val copy : t -> t
(** The same interior, a value of its own: rays tell interiors apart by
    identity. *)

val transform : Transform.t -> t -> t
(** Move the densities of its media (the interior itself when it has none:
    interiors are told apart by identity). *)

val fades_light : t -> bool
(** Whether a shadow ray fades inside: a fade distance and a fade power
    (POV-Ray 3.7 leaves light unfaded by [fade_power 0]). *)

(** {2 The interiors a ray is inside}

    A ray's media are the interiors it is inside, innermost first, each
    once. *)

val fresnel_ior : t -> t list -> float
(** [fresnel_ior inner media]: the index ratio POV-Ray weighs a fresnel
    reflection off a surface of [inner] by: [1 / relative_ior inner
    media], except for a ray leaving [inner] while inside other
    interiors too, where POV-Ray 3.7 takes the innermost interior's
    index over [inner]'s (1, no reflection, when [inner] is the
    innermost: glass inside a hollow object around the camera reflects
    nothing from within). *)

val relative_ior : t -> t list -> float
(** [relative_ior inner media]: the relative index of refraction across a
    surface of [inner] for a ray inside [media]. Entering or leaving is
    decided as POV-Ray does, by whether the ray is already inside
    [inner], not by the side of the surface (the children of a CSG share
    their parent's interior: in the overlap of a union of glass spheres
    the inner walls bend light as glass to air). Inlined where it is used
    (its result is not boxed). *)

val beyond : t -> t list -> t list
(** [beyond inner media]: the media past a surface of [inner], [inner]
    entered or left. A list is made once per domain for each pair met,
    and kept in a cache of 1,024 pairs (4 a set, by their slots): refracting
    through glass allocates nothing. *)

val number : t -> unit
(** Give the interior a new [slot] (numbers from a counter shared by all
    domains); done for every object's interior as a scene is made, before
    it renders. [default] keeps slot 0 (the parser copies it into every
    interior it reads). *)
