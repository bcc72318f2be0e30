(** POV-Ray 3.7's participating media ([media { }] in an interior): what
    a ray crossing the inside of a solid absorbs, emits and scatters.
    Coefficients are per unit of length, scaled at each point by the
    product of the media's densities. *)

type scattering = {
  kind : int;  (** 1 isotropic, 2 Mie hazy, 3 Mie murky, 4 Rayleigh, 5 Henyey-Greenstein *)
  color : Color.t;
  eccentricity : float;  (** Henyey-Greenstein's g (0) *)
  extinction : float;  (** how much of [color] dims the ray (1) *)
}

type t = {
  emission : Color.t;
  absorption : Color.t;
  scattering : scattering option;
  density : Pigment.t list;  (** multiplied; none: 1 everywhere *)
  meth : int;  (** sampling method, 2 or 3 (3) *)
  intervals : int;  (** 1; method 2 only *)
  samples : int;  (** minimum samples (10) *)
  samples_max : int;
  aa_threshold : float;  (** 0.1 *)
  aa_level : int;  (** 3 *)
  jitter : float;  (** 0; read and ignored: camlray never jitters *)
  confidence : float;  (** read; used by method 1 only *)
  variance : float;
  ratio : float;
  collect : bool;  (** photons: [collect off] leaves no media photons in it, and its samples' shadows as they are *)
  mutable bound : float;
      (** {!majorant}'s cache: -1 until it is first asked for (kept
          by [{ m with ... }] copies, which cannot change it once the
          scene is made: transformations move the densities only) *)
}

val default : t

val scattering : int -> Color.t -> scattering
(** [scattering kind colour] with eccentricity 0 and extinction 1. *)

val transform : Transform.t -> t -> t
(** Move the densities by a transform applied after their own. *)

val constant : t -> bool
(** No density pattern: the same everywhere. *)

val phase : scattering -> float -> float
(** [phase sc c]: POV-Ray's phase function for the cosine [c] between the
    light's direction of travel and the direction toward the eye, with
    POV-Ray 3.7's constants (media.cpp, and measured on its pictures):
    isotropic and Henyey-Greenstein average 1 over the sphere, Mie hazy
    1.1533, Mie murky 1.2468 and Rayleigh 1.0658. *)

val density_into : t -> Vec3.m -> Pigment.out -> Color.acc -> unit
(** [density_into m p scratch out]: the product of [m]'s densities at [p]
    (rgb), into [out]. Once the product is 0 the densities after it are
    not evaluated (their colours are finite: the product stays 0). *)

val pieces : t -> int
(** How many stretches an interval is sampled in: method 3 (POV-Ray 3.7,
    measured): [max 2 (samples / 2 + 1)] stretches of [1/(n+1)] of the
    interval each, read at their ends and middle, each weighing [1/n] of
    it; method 2: [samples * intervals] midpoints. *)

val add_extinction : t -> Vec3.m -> Pigment.out -> Color.acc -> Color.acc -> unit
(** [add_extinction m p pig dens out]: [m]'s extinction at [p]
    (absorption + extinction x scattering, times density) added into
    [out]; [pig], [dens]: scratch. *)

type span = { mutable lo : float; mutable hi : float }
(** A stretch of a ray, [lo] to [hi] along it (all floats: they are
    stored unboxed, so passing one allocates nothing) *)

val span : unit -> span

val transmittance_into : t list -> Ray.scratch -> span -> Color.acc -> unit
(** [transmittance_into ms r sp out]: [out] times what crosses the
    media [ms] from [sp.lo] to [sp.hi] along [r] (unit direction): exact
    for constant media, sampled as {!pieces} says otherwise. *)

val majorant : t -> float
(** An upper bound of the medium's extinction over all space, in every
    channel: the largest channel of [absorption + extinction x
    scattering] times each density's {!Pigment.bound}. Worked out on the
    first call and kept (Monte Carlo mode's tracking). *)
