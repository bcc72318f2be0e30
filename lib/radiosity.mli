(** POV-Ray 3.7's radiosity, as whitted mode computes it: its settings
    (global_settings' [radiosity { ... }]), the directions its gather rays
    take, the per-domain state of the gathers in progress, and the
    irradiance cache filled by a pretrace. The gather itself, which
    traces rays, is {!Whitted}'s. *)

type record = {
  px : float; py : float; pz : float;  (** where the gather was *)
  nx : float; ny : float; nz : float;  (** its normal *)
  ir : float; ig : float; ib : float;  (** the mean light found, before gray_threshold and brightness *)
  hmd : float;  (** the harmonic mean distance of what its rays met, clamped by minimum_reuse and maximum_reuse *)
  near : float;  (** the nearest distance met *)
  tx : float; ty : float; tz : float;  (** the unit direction of that nearest ray *)
}
(** A gather kept for reuse (Ward's irradiance cache, as POV-Ray keeps it). *)

type cache
(** The records of a render, by recursion depth: filled by a pretrace
    (one domain), then only read (by every domain). *)

val new_cache : unit -> cache

type t = {
  count : int;  (** rays of a top-level gather (35); deeper gathers shoot half as many per level, at least 5 *)
  recursion_limit : int;  (** bounces of indirect light (2), 1..20 *)
  brightness : float;  (** the gathered light's factor (1) *)
  error_bound : float;  (** how far a cache record is reused (1.8) *)
  nearest_count : int;  (** records averaged where a point is looked up (5), 1..20 *)
  gray_threshold : float;  (** how far the gathered light is made grey (0), 0..1 *)
  pretrace_start : float;  (** the coarsest pretrace's pixel size, a fraction of the image (0.08) *)
  pretrace_end : float;  (** the finest pretrace's (0.04) *)
  low_error_factor : float;  (** the error bound's factor during the pretrace (0.5) *)
  minimum_reuse : float;  (** the least reuse radius, a fraction of the distance to the camera (0.015) *)
  maximum_reuse : float;  (** the largest (0.2) *)
  adc_bailout : float;  (** the gather rays' ADC bailout (0.01) *)
  max_sample : float;  (** the brightest a gather ray may bring back (its largest channel; <= 0: no limit) *)
  always_sample : bool;  (** the final pass gathers anew where fewer than [nearest_count] records serve (off) *)
  normal : bool;  (** gather about the perturbed normal (off: the surface's own) *)
  media : bool;  (** gather rays see media (off) *)
  keep_ambient : bool;
      (** a scene of #version before 3.7 keeps its finishes' [ambient]
          beside the radiosity (POV-Ray's legacy rule); from 3.7 on,
          radiosity replaces it *)
  cache : cache;  (** the scene's own (the compiler makes one per scene) *)
}

val default : t
(** POV-Ray 3.7's defaults. *)

val rays : t -> int -> int
(** [rays r depth]: the rays of a gather at that recursion depth
    (0 at a camera ray's surfaces): max 5 (count / 2^depth). *)

val trace_level : int -> int
(** The trace level a gather ray at a depth starts from, in camlray's
    counting (a camera ray is level 1): POV-Ray's int (1.5 (depth + 1)),
    plus one. *)

val weight : t -> int -> float
(** The ADC weight of a gather ray at a depth: max (adc_bailout +
    epsilon) ((brightness / 2)^(depth + 1)) (POV-Ray's estimate). *)

val direction_into :
  Vec3.m -> int -> int -> float -> float -> Vec3.m -> unit
(** [direction_into n i count r1 r2 out]: the [i]th of [count] directions
    about the unit normal [n], cosine-weighted (a Hammersley set on the
    unit square, shifted by [(r1, r2)] modulo 1, mapped to the hemisphere
    by Malley's method: [sqrt u1] the sine's radius, [2 pi u2] the
    turn). The tangent frame is POV-Ray's: [x] = n x z normalised (n x y
    when n is within 0.9 of z), [z] = x x n. *)

val radical_inverse : int -> float
(** Van der Corput's base-2 radical inverse of an index, in [0, 1). *)

(** The gathers in progress on the calling domain. *)

val depth : unit -> int
(** The recursion depth of the ray being traced: 0 for a camera ray and
    the rays it spawns, d inside a depth-(d-1) gather. *)

val descend : unit -> unit
val ascend : unit -> unit
val reset_depth : unit -> unit

(** The irradiance cache. *)

val clear : cache -> unit
val filling : cache -> bool
(** Whether gathers add records (the pretrace) or only read them. *)

val set_filling : cache -> bool -> unit

val final : cache -> bool
(** Whether lookups follow the final pass's rules (the full error bound,
    any weight found serves, smooth weights at depth 0) rather than the
    pretrace's. *)

val set_final : cache -> bool -> unit
val set_picture : cache -> width:int -> height:int -> Float.Array.t -> unit
(** Keep the colours the final pass found at the centres of a [width] x
    [height] image's pixels (3 floats a pixel, by rows), which its
    picture then takes ([clear] forgets them). *)

val picture_into : cache -> width:int -> height:int -> int -> int -> Color.acc -> bool
(** [picture_into c ~width ~height x y out]: the kept colour of pixel
    [(x, y)] into [out], and [true], when colours of an image that size
    are kept; [false] otherwise. *)

val records : cache -> int -> int
(** Records kept at a depth. *)

val reuse_count : t -> int -> int
(** How much weight a lookup must find at a depth to be used without a
    gather during the pretrace: nearest_count at depth 0, at most 2 at
    depth 1, then 1 (POV-Ray's; compared with 4 times the weight). *)

val add : cache -> int -> record -> float -> unit
(** [add c depth r reach]: keep a record whose reach (its harmonic mean
    distance times the largest error bound at that depth) is [reach]. *)

(** {2 Samples traced ahead of their turn}

    The pretrace's samples, each traced after the ones before it have
    filled the cache, traced on several domains at once with the same
    result: a batch of samples is traced ahead, each seeing the cache as
    it was before the batch and the records of its own gathers; then,
    in turn, a sample none of whose lookups the records taken before it
    in the batch weigh in had the same lookups, and so the same gathers,
    as traced in turn, and its records are taken; another is traced
    again. *)

val speculate : cache -> bool -> unit
(** While on, gathers keep their records apart (per domain) and lookups
    are logged: set it before the batch's parallel loop, clear it after. *)

type outcome
(** What a sample traced ahead found: its records and its lookups; made
    once and filled again by each sample ({!end_sample}). *)

val outcome : unit -> outcome
(** An empty one. *)

val begin_sample : ?ahead:bool -> unit -> unit
(** Start a sample on the calling domain (its records and log emptied):
    traced ahead (its lookups logged), or ([~ahead:false]) in turn. *)

exception Abandoned
(** Raised by a lookup of a sample traced ahead that has logged 8192
    lookups: the sample is to be traced in turn. *)

val end_sample : outcome -> unit
(** The calling domain's sample's outcome, into [o] (what [o] held is
    dropped; the sample's lookups change places with [o]'s old buffer,
    not copied). *)

type batch

val batch : unit -> batch

val start_batch : batch -> unit
(** No record taken yet. *)

val conflicts : batch -> outcome -> bool
(** Whether a record taken in the batch weighs in one of the outcome's
    lookups (then the sample must be traced again). *)

val commit : cache -> batch -> outcome -> unit
(** Keep the outcome's records in the cache, in the order they were
    made, and note them as taken in the batch. *)

type sums = { mutable eb : float; mutable ws : float; mutable sr : float; mutable sg : float; mutable sb : float }
(** A lookup's error bound (set by the caller), total weight and
    weighted light. *)

val sums : unit -> sums
(** This domain's. *)

val lookup : cache -> int -> Vec3.m -> Vec3.m -> sums -> Color.acc -> unit
(** [lookup c depth q n sm out]: POV-Ray's reuse test of every record
    near [q] (of unit normal [n]) against the error bound [sm.eb]:
    distance over the record's reach plus 2 sqrt (1 - cos) of the normals
    under it, not in front of the point; each weighted 1 - e/eb (a smooth
    step of it at depth 0 in the final pass); the total weight into
    [sm.ws], the weighted mean light into [out] when it is positive.
    Allocates nothing (floats passed in and out through [sm]: as
    arguments or results they would be boxed). *)
