(** POV-Ray 3.7's photon map for caustics: the words of its [photons]
    blocks, and the map of photons stored on surfaces with the queries
    the shading asks of it. Shooting the photons is {!Caustics}'s; this
    module knows nothing of the scene.

    The map is a balanced kd-tree (each node splits its photons at the
    median of their widest axis), searched for the nearest photons of a
    point by a surface-flattened distance, d^2 (1 + 16 |n.v|) with v the
    offset from the point and n the surface normal, as POV-Ray 3.7's
    gather measures it (photons off the surface's plane count as
    farther). *)

(** {1 The words} *)

type flags = {
  target : float;  (** [target [F]]: the spacing multiplier; 0 when the object is not a target *)
  refraction : int;  (** [refraction on]: 1, [off]: -1, unsaid: 0 *)
  reflection : int;  (** likewise *)
  collect : bool;  (** [collect] (on unless [collect off]) *)
  pass_through : bool;
  split_union : bool;  (** a target union is shot child by child (true) *)
  area_light : bool;  (** a light's [area_light]: photons shot from each sample of its grid *)
}
(** An object's or a light's [photons { }] block. *)

val none : flags
(** Nothing said: not a target, collects. *)

val pushed : parent:flags -> flags -> flags
(** [pushed ~parent child]: a CSG's words pushed down to a child, as
    POV-Ray's parser does: what the parent says overrides the child's
    (target with its multiplier, pass_through, refraction and
    reflection on or off, collect off). *)

val merged : int -> int -> bool
(** Two words (1 on, -1 off, 0 unsaid) merged: one on and neither off. *)

val shoots : flags -> light:flags -> bool
(** Whether a light shoots photons at a target: their words merged, one
    of refraction or reflection on and not off. *)

val refracts : flags -> light:flags -> bool
(** Whether a surface refracts the photons of a light: on unless the
    light says off, or the light's on unless the object says off. *)

val reflects : flags -> light:flags -> bool

val blocks_shadow : flags -> light:flags -> bool
(** POV-Ray's rule for shadow rays when photons are on: a target that
    refracts the light's photons casts a full shadow on surfaces that
    collect photons (the light behind it comes from the photons). *)

(** {1 The settings} *)

type map

type settings = {
  spacing : float;  (** 1.0 when neither spacing nor count is given *)
  count : int;  (** 0: [spacing] rules *)
  gather_min : int;  (** 20 *)
  gather_max : int;  (** 100 *)
  jitter : float;  (** 0.4 *)
  max_trace_level : int;  (** -1: the scene's *)
  adc_bailout : float;  (** negative: the scene's *)
  autostop : float;  (** 0.5 *)
  expand_tolerance : float;  (** 0.2 *)
  expand_min : int;  (** 35 *)
  radius : float;  (** the gather radius; not positive: estimated from the map *)
  radius_mult : float;  (** 1 *)
  media_steps : int;  (** [media STEPS]: the most media photons a stretch of ray deposits (0: none) *)
  media_factor : float;  (** [media STEPS, FACTOR]: their spacing along the ray, in [spacing]s (1) *)
  media_radius : float;  (** [radius]'s third value: the media map's gather radius (estimated when not positive) *)
  media_mult : float;  (** its fourth: a multiplier (1) *)
  state : state;
}

and state = {
  mutable map : map option;  (** the surfaces' photons, shot once before the first render *)
  mutable media_map : map option;  (** the media's *)
}

val default_settings : unit -> settings
(** POV-Ray's defaults when a [photons] block is present (a fresh state). *)

(** {1 The map} *)

type store
(** Photons gathered while shooting, before the tree is built. *)

val store : unit -> store
val add : store -> float -> float -> float -> r:float -> g:float -> b:float -> float -> float -> float -> unit
(** [add st x y z ~r ~g ~b dx dy dz]: a photon at [(x, y, z)] carrying
    that flux, come from the unit direction [(dx, dy, dz)] (toward where
    it came from). *)

val stored : store -> int

val append : store -> store -> unit
(** [append st src]: [src]'s photons after [st]'s. *)

val build : ?seed:int -> ?volume:bool -> settings -> store -> map
(** The kd-tree over the photons, with its gather radius: the settings'
    [radius] when positive, else POV-Ray's estimate (the mean density
    around random photons at their [gather_max] nearest, a radius that
    holds [gather_max] photons at that density, widened by the share of
    photons whose density is well below the mean), times
    [radius_mult]. [seed] picks the random photons (the same map each
    time). With [volume], a media map: densities per volume, the radius
    [media_radius] or the one holding [gather_max] at the mean density,
    widened as above, times [media_mult] and 2 (POV-Ray's rules). *)

val size : map -> int
val radius : map -> float

(** {1 Queries} *)

type query
(** A domain's search state (the nearest photons found, at most
    [gather_max]); {!gather} refills it. *)

val query : unit -> query
(** The calling domain's. *)

val nearest : map -> query -> float -> float -> float -> radius:float -> int
(** [nearest m q x y z ~radius]: the at most [gather_max] photons nearest
    [(x, y, z)] within [radius], by plain distance; their number. *)

val gather : map -> query -> Vec3.m -> Vec3.m -> unit
(** [gather m q p n]: POV-Ray's adaptive gather at [p] of normal [n]
    (flattened distance): the nearest photons within the map's radius,
    and when fewer than [gather_min] are found, within three times it if
    the density found there is close (relative change below
    [expand_tolerance]) or the count small (below [expand_min]). Read
    them with {!found}, {!photon} and {!area}. *)

val gather_volume : map -> query -> Vec3.m -> unit
(** [gather_volume m q p]: {!gather} in a media map: plain distance, no
    normal. Read the result with {!found}, {!photon} and {!volume}. *)

val found : query -> int
val volume : query -> float
(** 4/3 pi r^3 of the last gather (r as for {!area}). *)

val area : query -> float
(** pi r^2 of the last gather: r the search radius when it held no more
    photons than it keeps, else the (flattened) distance of the farthest
    photon kept. *)

val index : query -> int -> int
(** [index q i]: the map's index of the [i]th photon found. *)

val position : map -> int -> int -> float
(** [position m i k]: coordinate [k] (0, 1, 2) of photon [i]. *)

val flux : map -> int -> int -> float
val direction : map -> int -> int -> float
