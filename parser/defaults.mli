(** Parse-time settings that change meaning as a file is read: the
    language version ([#version]) and the [#default] texture. One parse
    runs at a time in a process (the scene language is read on one
    domain); {!reset} starts a fresh parse. *)

val reset : unit -> unit
val version : unit -> float

val charset : unit -> [ `Ascii | `Utf8 | `Sys ]
(** global_settings' [charset] (POV-Ray's default: ascii): how a text
    object's string becomes characters. *)

val set_charset : [ `Ascii | `Utf8 | `Sys ] -> unit
val set_version : float -> unit
val set_noise_generator : int -> unit
(** global_settings' [noise_generator]: the scene's generator
    ([Camlray.Pattern.scene_noise_generator]) from here on, which no later
    [#version] changes. Until one is given, each [#version] sets it as
    POV-Ray does, 1 (the original noise) below 3.5, else 2; {!reset} sets
    2 (f_noise3d evaluated while parsing reads it). *)

val noise_for_version : float -> int
(** The generator a scene naming none gets under a language version: 1
    below 3.5, else 2. *)

val restore_version : float -> unit
(** Put back the version an included file started with, at its end
    (POV-Ray's rule); not a new [#version]. *)

val version_given : unit -> bool
val first_version : unit -> float option
(** The first [#version] of the main file, if it came before any scene
    item. *)

val mark_item : unit -> unit
(** Note that a scene item has been read (later [#version]s do not change
    the gamma rules). *)

val warn_once : string -> Loc.t -> string -> unit
(** [warn_once key loc msg]: the warning, the first time [key] is met
    in this parse. *)

val texture : unit -> Camlray.Texture.layer

val texture_set : unit -> bool
(** Whether a [#default] has changed the texture since {!reset}. *)
val set_finish : Camlray.Finish.t -> unit
val set_pigment : Camlray.Pigment.t -> unit
val set_normal : Camlray.Normal.t option -> unit

val normal_template : unit -> Camlray.Normal.t option
(** What a normal written from here on starts from (POV-Ray copies the
    [#default] normal into each new one): the [#default] normal, or,
    where that gave only modifiers ([bump_size 1.5], a [scale]), a normal
    carrying them; [None] before any. *)

val set_normal_template : Camlray.Normal.t option -> unit

val set_finder : (Loc.t -> string -> string option) -> unit
(** How the parse finds a file a scene names outside [#include] (a
    font): the include path, within the reads the scene is allowed. *)

val find_file : Loc.t -> string -> string option
(** The file found by the finder set for this parse ([None] before one
    is set). *)
