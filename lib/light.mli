(** Light sources (POV-Ray 3.7 semantics, pov-facts.md 5.3). *)

type kind =
  | Point
  | Spot of {
      point_at : Vec3.t;
      radius : float;
      falloff : float;
      tightness : float;
      cos_radius : float;
      cos_falloff : float;
    }
      (** angles in degrees (half-angles from the axis); their cosines
          made once ({!spot}) *)
  | Parallel of { point_at : Vec3.t }
  | Cylinder of { point_at : Vec3.t; radius : float; falloff : float; tightness : float }
      (** POV-Ray's cylindrical light: rays parallel to [point_at -
          position]; [radius] and [falloff] are distances from that axis
          (POV-Ray's defaults 0.75 and 1, tightness 0); nothing is lit
          behind the plane through the light across its axis *)

val spot : point_at:Vec3.t -> radius:float -> falloff:float -> tightness:float -> kind
(** A spot light's kind, with the cosines of its angles. *)

type area = {
  axis1 : Vec3.t;
  axis2 : Vec3.t;
  n1 : int;  (** samples along [axis1], at least 1 *)
  n2 : int;
  adaptive : int;  (** levels subdivided unconditionally (100 without [adaptive]) *)
  circular : bool;
      (** samples moved onto a disc as POV-Ray moves them: the offsets
          [(u, v)] in [[-1/2, 1/2]] plus 0.001 each, then along their
          direction to the distance of the larger (set by [orient] too,
          as POV-Ray's parser sets it, when both sizes exceed 1) *)
  orient : bool;
      (** axes turned to face each lit point, as POV-Ray builds them: with
          [d] the unit direction toward the light (a cylindrical or
          parallel light's, from its point_at to it), the first along
          [d x z] ([d x y] within 0.01 of [+-z]), the second along [d x]
          the first, both as long as [axis1] *)
  jitter : bool;  (** parsed, ignored: camlray's area lights are never jittered *)
  area_illumination : bool;
      (** diffuse and highlights computed per sample and averaged like the
          shadows (close to POV-Ray: about 42 dB on a test scene, not
          exact); off: shading uses the light's centre *)
  offsets1 : Float.Array.t;
      (** [offset n1 i] at [i], made once by {!area} (a record changed
          with [with] keeps [n1] and [n2] as they were) *)
  offsets2 : Float.Array.t;  (** [offset n2 j] at [j] *)
}
(** [area_light <A1>, <A2>, n1, n2 ...]: shadows are averaged over a grid
    of point samples reaching the ends of the axes. *)

type t = {
  position : Vec3.t;
  color : Color.t;
  kind : kind;
  fade_distance : float;
  fade_power : float;
  shadowless : bool;
  area : area option;
  media_interaction : bool;  (** scattered by media (true; a shadowless light never is) *)
  media_attenuation : bool;  (** dimmed by atmospheric media (false) *)
  projected_through : Object.t option;
      (** POV-Ray's [projected_through]: the light reaches a point only
          when the ray from the point toward the light meets this object
          (never drawn, casting no shadow) before the light; what lies
          between that crossing and the light casts no shadow *)
  photons : Photon.flags;  (** its [photons { }] words (refraction, reflection, area_light) *)
}

val point : Vec3.t -> Color.t -> t

val area : Vec3.t -> Vec3.t -> int -> int -> area
(** An area light grid with the defaults (adaptive 100, no circular,
    orient, jitter, area_illumination). *)

val attenuation : t -> Vec3.t -> float
(** Spot cone, cylinder and distance fade factor for light arriving at a
    point. *)

val cylinder_factor : radius:float -> falloff:float -> tightness:float -> float -> float
(** [cylinder_factor ~radius ~falloff ~tightness d]: POV-Ray's
    attenuation of a cylindrical light at the distance [d] from its axis:
    0 from [falloff] out; else, with [x = 1 - d / falloff], [x ^
    tightness], times the smooth step [(3 - 2s) s^2], [s = x / (1 -
    radius / falloff)], between [radius] and [falloff] (when [radius] >
    0). *)

val beam : t -> Vec3.m -> float
(** The spotlight's or cylindrical light's factor at a point (1 for
    other lights), without the light's fade: what a photon shot toward
    the point starts with. *)

val attenuation_m : t -> Vec3.m -> float
(** The same at a point written in place, in scalars (inlined: nothing
    allocated). *)

val attenuation_at : t -> float -> float -> float -> Vec3.m -> float
(** [attenuation_at l x y z p]: {!attenuation_m} of the light as if it
    stood at [(x, y, z)] (a point of an area light). *)

val attenuation_shifted : t -> float -> float -> float -> Vec3.m -> float
(** The same, but a spotlight's axis stays the light's own (from its
    centre toward its point_at), moved to [(x, y, z)] without turning: the
    angle is from that direction (POV-Ray's rule for the samples of an
    area light with [area_illumination]). *)

val direction_to : t -> Vec3.t -> Vec3.t * float
(** Unit vector from the point towards the light, and the distance over
    which shadow rays must look (for parallel and cylindrical lights: to
    the plane through the light perpendicular to its direction, negative
    behind it). *)

(** A direction to a light and its distance, in a reusable record. *)
type dir = { mutable lx : float; mutable ly : float; mutable lz : float; mutable dist : float }

val dir : unit -> dir

val direction_into : t -> Vec3.m -> dir -> unit
(** [direction_to] from a point written in place, into a record: nothing
    allocated. *)

val direction_at : t -> float -> float -> float -> Vec3.m -> dir -> unit
(** [direction_at l x y z p o]: {!direction_into} for the light as if it
    stood at [(x, y, z)]. *)

val position_at : t -> area -> Vec3.t -> float -> float -> Vec3.t
(** [position_at l a p u v], [u, v] in [[-1/2, 1/2]]: the point
    [position + u axis1 + v axis2] of the light's rectangle as seen from
    [p] (moved onto the disc when [circular], the axes turned to face [p]
    when [orient]). *)

val position_into : t -> area -> Vec3.m -> float -> float -> Vec3.m -> unit
(** [position_into l a p u v out]: {!position_at} from a point written in
    place, into [out], nothing allocated ({!position_at} goes through
    it). *)

(** The two axes of an area light's grid as seen from a point (turned
    to face it when [orient]), written in place: found once for all the
    samples seen from one point. *)
type axes = {
  mutable ux : float;
  mutable uy : float;
  mutable uz : float;
  mutable vx : float;
  mutable vy : float;
  mutable vz : float;
}

val axes : unit -> axes

val axes_into : t -> area -> Vec3.m -> axes -> unit
(** [axes_into l a p o]: the axes of [a] seen from [p], into [o]. *)

val sample_on : t -> area -> axes -> int -> int -> Vec3.m -> unit
(** [sample_on l a o i j out]: grid sample [(i, j)] on the axes [o] (from
    {!axes_into}), into [out]: {!sample_into} from the point [o] was found
    for, the same arithmetic. *)

val sample_into : t -> area -> Vec3.m -> int -> int -> Vec3.m -> unit
(** [sample_into l a p i j out]: {!position_into} at grid sample [(i,
    j)] (its offsets kept by the area), nothing allocated. *)

val sample_position : t -> area -> Vec3.t -> int -> int -> Vec3.t
(** [sample_position l a p i j]: where sample [(i, j)] of an area light
    is, as seen from the lit point [p] ([orient] and [circular] applied). *)

val average_area : area -> (int -> int -> Color.t) -> Color.t
(** POV-Ray's recursive average of area-light samples: the index
    rectangle is split into quadrants at the floor and ceiling of its
    midpoint, the result is the mean of the quadrants, and a rectangle at
    most one step wide is the mean of its four corners; past the first
    [adaptive] levels a rectangle is only split when two adjacent corners
    differ by more than 0.1. Each sample is computed once. *)

val average_area_into : area -> 'c -> ('c -> int -> int -> Color.acc -> unit) -> Color.acc -> unit
(** [average_area_into a ctx f out]: {!average_area} of the samples [f ctx
    i j] writes, into [out] ({!average_area} goes through it). With [f] a
    closed function, nothing is allocated: the samples and the partial
    means are kept in per-domain arrays. *)

val offset : int -> int -> float
(** [offset n i]: where sample [i] of [n] lies along an axis, in
    [[-1/2, 1/2]]. *)
