(** A [fog { ... }] block as it is read: its items in order, then the
    fog they describe ({!Camlray.Fog.t}), checked with located errors. *)

type t

val empty : t
(** POV-Ray's defaults: fog_type 1, distance 0 (no fog), black, fog_offset
    0, fog_alt 0, up y, turb_depth 0.5, octaves 6, omega 0.5, lambda 2. *)

type item = t -> t

val value : Loc.t -> Value.t -> item
(** A bare value: a number is the distance, a vector the colour. *)

val distance : float -> item
val color : Camlray.Color.rgbft -> item
val kind : Loc.t -> int -> item
(** [fog_type]: 1 (constant) or 2 (ground); anything else is an error. *)

val offset : float -> item
val alt : float -> item
val up : Camlray.Vec3.t -> item
val turbulence : Camlray.Vec3.t -> item
val turb_depth : float -> item
val octaves : Loc.t -> int -> item
val omega : float -> item
val lambda : float -> item
val transform : Camlray.Transform.t -> item
(** Transformations turn the up vector (POV-Ray moves nothing else). *)

val fog : Loc.t -> t -> Camlray.Fog.t
(** The fog; a ground fog needs [fog_alt > 0] and a non-zero up vector. *)
