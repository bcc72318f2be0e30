(** Helpers for the semantic actions of the grammar files ([grammar_*.mly]). *)

val loc : Lexing.position * Lexing.position -> Loc.t
val v3 : Lexing.position * Lexing.position -> Value.t -> Camlray.Vec3.t
val fl : Lexing.position * Lexing.position -> Value.t -> float

val with_texture : Lexing.position * Lexing.position -> (Camlray.Texture.layer -> Camlray.Texture.layer) -> Sdl.obj -> Sdl.obj
(** Change the top texture layer of an object (starting from the
    [#default] texture when it has none). *)

val light_param :
  Lexing.position * Lexing.position -> string -> ?parallel:bool -> (Sdl.light -> Sdl.light) -> Sdl.obj -> Sdl.obj
(** [light_param loc what f]: set a spotlight's or a cylinder's parameter
    [what]; an error at [loc] on a point light (with [~parallel:true], a
    parallel point light takes it too: point_at). *)

val projected_through : Lexing.position * Lexing.position -> Sdl.obj -> Sdl.obj -> Sdl.obj
(** [projected_through loc p light]: the light's [projected_through]
    object (an error at [loc] when it has one already), kept so that only
    the transformations written after it move it. *)
val light_field : (Sdl.light -> Sdl.light) -> Sdl.obj -> Sdl.obj

val nonzero_scale : Lexing.position * Lexing.position -> Camlray.Vec3.t -> Camlray.Vec3.t
(** POV-Ray replaces zero scale components by 1, with a warning. *)
val area_field : (Camlray.Light.area -> Camlray.Light.area) -> Sdl.obj -> Sdl.obj
(** Change the area-light settings of a light (no effect before [area_light]). *)
val layered : Loc.t -> above:Camlray.Texture.t -> below:Camlray.Texture.t -> Camlray.Texture.t
(** [above] layered on top of [below]; a located error where POV-Ray
    refuses it (see {!Camlray.Texture.layering}). *)

val top_layer : (Camlray.Texture.layer -> Camlray.Texture.layer) -> Camlray.Texture.t -> Camlray.Texture.t
(** Change the top layer of a texture. *)
val old_entry :
  Lexing.position * Lexing.position -> Value.t -> Lexing.position * Lexing.position -> Value.t ->
  Camlray.Pigment.t * Camlray.Pigment.t -> (float * Camlray.Pigment.t) list
(** A colour map entry in the old form [[v1, v2 colour1 colour2]]. *)
val tmap_pattern : Texdesc.modifier -> Camlray.Texture.layer -> Camlray.Texture.layer
(** Apply a pattern modifier (turbulence, frequency, ...) to a patterned
    texture layer. *)

val moved : Texdesc.modifier list -> Camlray.Normal.t option -> Camlray.Normal.t option
(** A normal with more modifiers (transformations, pattern modifiers). *)

val flat : Camlray.Normal.t option -> Camlray.Normal.t
(** A normal_map entry written without a pattern: flat. *)

val slope :
  Lexing.position * Lexing.position -> Value.t -> (float * float) option ->
  ((Lexing.position * Lexing.position) * Value.t * (float * float) option) option -> Camlray.Pattern.kind
(** POV-Ray's [slope { <dir> [, lo, hi] [altitude <dir> [, lo, hi]] }]:
    the directions normalised, their lengths the weights. *)


val orientation : Lexing.position * Lexing.position -> Value.t -> Camlray.Vec3.t
(** A mapping warp's orientation, normalised (an error if zero). *)

val mapping : [> `Orient of Camlray.Vec3.t | `Dist_exp of float ] list -> Camlray.Vec3.t * float
(** The orientation and [dist_exp] a mapping warp's options leave: the
    last of each, z and 0 by default. *)

val average_texture : Loc.t -> Camlray.Texture.layer -> Camlray.Texture.layer
(** [texture { average texture_map { ... } }] checked (a map, weights not
    summing to 0) and its weights divided by their sum. *)

val facets_elsewhere : Lexing.position * Lexing.position -> 'a
(** [facets] written in a pigment or a texture: a located error (POV-Ray
    refuses it too: it is a normal-only pattern). *)

val rainbow :
  Loc.t ->
  [ `Angle of float
  | `Width of float
  | `Distance of float
  | `Jitter of float
  | `Direction of Loc.t * Camlray.Vec3.t
  | `Up of Loc.t * Camlray.Vec3.t
  | `Arc of Loc.t * float
  | `Falloff of Loc.t * float
  | `Map of (float * Camlray.Pigment.t) array ]
  list ->
  Camlray.Rainbow.t
(** A [rainbow { }] from its items in order, POV-Ray's checks as located
    errors. *)

val image_channel : Lexing.position * Lexing.position -> string -> [ `Filter | `Transmit ]
(** An image_map's [filter ...] or [transmit ...]: any other channel is a
    located error. *)

val readable_kind : Lexing.position * Lexing.position -> string -> unit
(** An image_map's, image_pattern's or bump_map's file type: jpeg, gif
    and ppm are read (png has its own token); any other is a located
    error. *)

val vector_literal : Loc.t -> Value.t list -> Value.t
(** The action of a vector literal [< c1, c2, ... >], its components in
    order: their count checked (2 to 5, 12, or a polynomial's
    coefficients), each a float. Shared with {!Quick}. *)

val call_function : Loc.t -> Fn.t -> Value.t list -> Value.t
(** The action of a declared function's call [F(a, b, ...)]: the
    arguments as floats, then the call. Shared with {!Quick}. *)

type rad_item = Loc.t * string * (Loc.t * Value.t) option * (Loc.t * Value.t) option
(** A radiosity block's word, its value and a second value after a comma. *)

val radiosity : rad_item list -> Camlray.Radiosity.t
(** global_settings' [radiosity { ... }] from POV-Ray 3.7's defaults. *)

val object_radiosity : Loc.t -> rad_item list -> unit
(** An object's [radiosity { importance ... }]: checked, warned about once, ignored. *)

type photon_item = Loc.t * string * (Loc.t * Value.t) list
(** A word of a [photons] block and its values. *)

val photons : photon_item list -> Camlray.Photon.settings
(** global_settings' [photons { }] block, POV-Ray's defaults for what it does not say. *)

val object_photons : photon_item list -> Sdl.obj -> Sdl.obj
(** An object's (target, refraction, reflection, collect, pass_through,
    split_union) or a light's (refraction, reflection, area_light)
    [photons { }] words, over those already said. *)
