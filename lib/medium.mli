(** Participating media in Monte Carlo mode: the media of the interiors
    a path's stretch runs in ({!Media}: absorption, emission, scattering
    with POV-Ray's phase functions, density patterns) and, in the open,
    the scene's atmospheric media, as a physical medium.

    Coefficients per unit of length at a point: extinction
    [absorption + extinction x scattering] (POV-Ray's), scattering
    [scattering] and emitted radiance [emission] (each times the
    media's densities), summed over the media there. Homogeneous media
    (no density) are sampled exactly: the emission integrated in closed
    form, a scattering distance drawn from the exponential of a channel
    chosen in proportion to the path's throughput, the weights by the
    mixture's density. Media with densities are tracked against a
    majorant ({!Media.majorant}): weighted delta tracking for a path's
    stretch, ratio tracking for a shadow ray's; both unbiased, with
    Russian roulette on small weights and a cap of {!steps_max} steps (a
    path still alive after that many null collisions is dropped: the one
    bias, reached only where the majorant's optical depth over the
    stretch is in the tens of thousands).

    The phase functions are POV-Ray's shapes ({!Media.phase}) made
    densities: divided by 4 pi and by their mean over the sphere (1 for
    isotropic and Henyey-Greenstein, POV-Ray's constants give 1.1533 for
    Mie hazy, 1.2468 for Mie murky, 1.0658 for Rayleigh), so that each
    integrates to 1 and an albedo 1 medium conserves energy. POV-Ray's
    own single scattering of a light of colour [c] is [scattering x
    phase x c]; Monte Carlo mode's light of colour [c] has intensity
    [pi c], so its single scattering is [scattering x phase x c / 4]
    (divided by the mean for the three).

    The working state is a record per domain; nothing is allocated. *)

type nums = {
  mutable len : float;  (** the stretch's length (set by the caller) *)
  mutable t : float;  (** where the medium scattered, along the stretch *)
  mutable maj : float;
  mutable u : float;
  mutable tot : float;
  mutable pick : float;
  mutable ph : float;  (** {!phase_at}'s value, per steradian *)
  mutable pdf : float;  (** the density with which {!sample_phase} picks a direction *)
}

type t = {
  n : nums;
  q : Vec3.m;
  pig : Pigment.out;
  dens : Color.acc;
  ext : Color.acc;
  sca : Color.acc;
  emi : Color.acc;
  sci : Color.acc;
  mutable phase : Media.scattering;  (** the scattering medium chosen where the medium scattered *)
  w : Color.acc;  (** what a stretch's throughput is multiplied by *)
  em : Color.acc;  (** the light a stretch's media emit toward its start (before {!w}) *)
  mutable scattered : bool;  (** the stretch ended in the medium, at [n.t] *)
  lw : Color.acc;
}

val get : unit -> t
(** The calling domain's record. *)

val present : Interior.t list -> Media.t list -> bool
(** [present inside air]: some medium is there. *)

val steps_max : int

val segment :
  t -> Sampler.t -> depth:int -> dim:int -> Interior.t list -> Media.t list -> Vec3.m -> Vec3.m -> Color.acc -> unit
(** [segment md s ~depth ~dim inside air o d thr]: a path's stretch of
    [md.n.len] units from [o] along the unit vector [d] through the media
    of [inside] and [air], for a path whose throughput is [thr]: sets
    [md.em] (emitted light arriving at [o], to be multiplied by [thr]),
    [md.w] (the throughput's factor) and whether and where it scattered
    ([md.scattered], [md.n.t]; then [md.phase] is the medium to scatter
    by). Random numbers: dimensions [dim] and [dim + 1] of [s] for
    homogeneous media, its tracking range for [depth] otherwise. *)

val shadow_dim : depth:int -> which:int -> cross:int -> int
(** The first dimension of a shadow ray's stretch's tracking range. *)

val transmittance :
  t -> Sampler.t -> int -> Interior.t list -> Media.t list -> Vec3.m -> Vec3.m -> Color.acc -> unit
(** [transmittance md s dim inside air o d out]: [out] times the
    transmittance of [md.n.len] units from [o] along the unit vector [d]
    (exact for homogeneous media, ratio tracking from dimension [dim]
    otherwise). *)

val phase_at : t -> Media.scattering -> float -> unit
(** [phase_at md sc c]: [sc]'s phase function (per steradian) for the
    cosine [c] (see below) into
    [md.n.ph], and the density of {!sample_phase} there into
    [md.n.pdf]. [c] is the dot product of the direction toward the light
    and the direction the path arrived along. *)

val sample_phase : t -> Media.scattering -> Vec3.m -> float -> float -> Vec3.m -> unit
(** [sample_phase md sc d u v wi]: a direction toward the light into
    [wi] for a path that arrived along [d], then {!phase_at} for it
    (Henyey-Greenstein and isotropic exactly, the others from a table:
    the weight is [md.n.ph /. md.n.pdf]). *)

val inv4pi : float
(** 1 / (4 pi): the density of a direction uniform over the sphere. *)
