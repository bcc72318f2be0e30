(** Where a ray crosses the light of spotlights: POV-Ray 3.7's
    light-source intervals. Media along a ray are sampled stretch by
    stretch, the ray cut where it enters and leaves each spotlight's cone
    (its [falloff] cone), so that a thin beam is sampled on its own and
    never falls between two samples. Distances are along a ray of unit
    direction, from its origin. *)

val max_distance : float
(** Where a stretch that runs on inside a cone for ever is cut: POV-Ray's
    [MAX_DISTANCE], 1e7 (it matters to rays that meet nothing, which
    cross 2e10 units of atmosphere). *)

(** A stretch of a ray, written in place. *)
type span = { mutable lo : float; mutable hi : float }

val span : unit -> span

val cone : Light.t -> Ray.scratch -> span -> bool
(** [cone l r out]: whether the ray [r] (unit direction) crosses the cone
    of the spotlight [l] (apex at the light, axis toward [point_at],
    half-angle [falloff], one nappe: what lies ahead of the light), and
    if so the stretch of the ray's line inside it into [out] (it may lie
    behind the origin, from [-infinity]; it ends at {!max_distance} at
    most);
    [false] for lights other than spotlights and for a cone of 90 degrees
    or more. *)

val cylinder : Light.t -> Ray.scratch -> span -> bool
(** [cylinder l r out]: POV-Ray 3.7's stretch of the ray [r] (unit
    direction) lit by the cylindrical light [l]: where its line runs
    within [falloff] of the light's axis, with POV-Ray's rules at the
    plane through the light (the stretch starts at the ray's origin when
    the line comes from behind that plane; a ray that leaves the lit side
    gets a stretch ending behind its origin, so nothing; a ray exactly
    along the axis gets none); [false] for other lights. *)

(** The stretches of one ray, lit and unlit, in order (per-domain
    scratch: grows with the scene's lights, never shrinks). *)
type t

val make : unit -> t

val cut : t -> Light.t array -> Ray.scratch -> float -> unit
(** [cut t lights r len]: the stretches of [[0, len]] along [r] as POV-Ray
    3.7 makes them from its [media_interaction] lights (not
    shadowless ones: fill lights, which its media leave out): each spotlight
    lights the part of its cone within the ray (a cylindrical light its
    {!cylinder} stretch) (kept when it starts
    before [len] and ends past 0.001), any other light all of it; the lit
    parts, merged where they overlap, are the lit stretches, the gaps
    between them and the ends of the ray the unlit ones. No light: one
    unlit stretch. Sets [r.far] to [len] (the length is read from there,
    unboxed). *)

val lights : t -> int -> float -> bool
(** [lights t i x]: whether light [i] (its index in the array given to
    {!cut}) lights the ray at [x] (POV-Ray leaves a light out of the
    samples outside its lit part). *)

val count : t -> int
val lo : t -> int -> float
val hi : t -> int -> float
val is_lit : t -> int -> bool
