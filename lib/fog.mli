(** POV-Ray 3.7's [fog]: along a ray in the open (inside no solid, or only
    hollow ones) the colour seen is blended with the fog's colour by the
    fog's transmittance over the distance travelled. Several fogs combine
    as POV-Ray combines them. *)

type kind =
  | Constant  (** [fog_type 1]: transmittance [exp (-d / distance)] *)
  | Ground of { offset : float; alt : float; up : Vec3.t }
      (** [fog_type 2]: density 1 below [offset] along [up] (unit), [1 /
          (1 + h^2)] at [h] altitudes above it *)

type turbulence = {
  amount : Vec3.t;  (** scales the point where the noise is read *)
  depth : float;  (** [turb_depth] (0.5); it, omega and lambda in single precision, as POV-Ray keeps them *)
  octaves : int;  (** 6 *)
  omega : float;  (** 0.5 *)
  lambda : float;  (** 2 *)
}

type t = { kind : kind; distance : float; color : Color.rgbft; turbulence : turbulence option }

val missed : float
(** The distance a ray that meets nothing travels through fog: POV-Ray's
    [2e10] (so the sky is fogged through and through, except where a
    ground fog thins out above its altitude). *)

val transmittance : t -> Vec3.m -> Vec3.m -> float -> float
(** [transmittance f origin dir width]: the fraction of the light that
    crosses [width] units of [f] from [origin] along the unit vector
    [dir], before the fog's transmit floor (with turbulence, POV-Ray's
    Turbulence of the scene's noise generator halfway along thins it,
    as POV-Ray 3.7 computes it). *)

val apply : t list -> Vec3.m -> Vec3.m -> float -> Color.acc -> unit
(** [apply fogs origin dir t c]: the colour [c] seen at distance [t] (in
    units of [dir], any length; [infinity] for a ray that met nothing)
    along the ray, as it arrives through every fog: [c] is attenuated by
    each fog's transmittance [a] (at least its [transmit]), tinted by its
    [filter], and [(1 - a)] of its colour is added. Fogs of zero distance
    are skipped. *)

val dim : t list -> Vec3.m -> Vec3.m -> float -> Color.acc -> unit
(** [dim fogs origin dir width c]: the light [c] of a shadow ray that
    crosses [width] units of the fogs from [origin] along the unit vector
    [dir] (POV-Ray does this for lights with [media_attenuation on]):
    attenuated and tinted as in {!apply}, with no fog colour added. *)

val blend_into : t list -> Vec3.m -> Vec3.m -> float -> Color.acc -> Color.acc -> unit
(** [blend_into fogs origin dir width att add]: what {!apply} does to a
    colour seen [width] units away ([infinity]: a ray that met nothing)
    from [origin] along the unit vector [dir], as the two parts of
    [att * c + add]: the attenuation [att] (floor and filter tint
    included) and the fogs' colour [add] (Monte Carlo mode applies it to
    every path segment in the open). *)
