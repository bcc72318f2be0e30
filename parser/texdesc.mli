(** Building pigments, normals and sky spheres from the modifiers written
    in a [pigment { }] or [normal { }] block (grammar_texture.mly's
    semantic actions). A modifier is a function on {!pat}, applied in the
    written order. *)

open Camlray

type pat = {
  pattern : Pattern.t option;  (** [None]: a plain colour or identifier *)
  base : Pigment.t;  (** for [None]: the colour or declared pigment *)
  entries : (float * Pigment.t) array option;  (** colour_map / pigment_map *)
  cells : Pigment.t list;  (** block pattern colours, in written order *)
  xform : Transform.t;
  amount : float;  (** normals: bump amount *)
  average : bool;  (** [average pigment_map]: the entries' values are weights *)
  slope : Float.Array.t;  (** normals: [slope_map] (see {!Normal.t}) *)
  accuracy : float;  (** normals: the slope's sample distance *)
  nmap : (float * Normal.t) array option;  (** normals: [normal_map] (an average's weights) *)
  ncells : Normal.t list;  (** normals: block pattern normals, in written order *)
  bump : Bump_map.t option;  (** normals: a [bump_map]'s image *)
  facets : Facets.t option;
      (** normals: [facets] (then [pattern] only carries the warps and
          turbulence) *)
  uv : Normal.t option;
      (** normals: a uv-mapped normal being modified: only
          transformations reach it ({!Normal.transform}); POV-Ray ignores
          the other modifiers of a uv-mapped normal (measured) *)
  carrier : Pattern.t option;
      (** the warps and turbulence written on what has no pattern of its
          own (an image map, an average, a bump map): a pattern whose
          kind is unused *)
}

type modifier = pat -> pat

val of_pigment : Pigment.t -> pat
val of_pattern : Pattern.kind -> pat

val of_normal_pattern : Pattern.kind -> pat
(** A normal's pattern, starting from the [#default] normal (its amount,
    transformations, turbulence and warps), as POV-Ray copies it. *)
val average : unit -> pat

val facets : unit -> pat
(** [normal { facets }]: POV-Ray's defaults (size 0.1, coords 0, metric 2)
    until changed. *)

val facets_mod : Loc.t -> string -> (Facets.t -> Facets.t) -> modifier
(** [facets_mod loc word f]: [coords] or [size] (named [word]), which
    only facets takes (a located error elsewhere). *)
val apply : modifier list -> pat -> pat

val pigment : pat -> Pigment.t
val normal : pat -> Normal.t
(** A leaf, or a map of normals: [normal_map] over a pattern, [average]
    (weights divided by their sum), a block pattern's list. *)

val of_normal : Normal.t -> pat

val bump_map : Loc.t -> string -> index:bool option -> interpolate:int -> once:bool -> pat
(** [normal { bump_map { png FILE ... } }]: the image's heights, the
    grey of its colours (not gamma-decoded, as POV-Ray); bump size 0.5 (POV-Ray's)
    until set. A palette image read by index ([use_index]: POV-Ray
    3.7 reads colours by default) is refused. Errors are located. *)
(** A declared normal, to be modified further. *)

val normal_map : Loc.t -> (float * Normal.t) list -> modifier
(** [normal_map { [v N] ... }]: at least one entry, by rising value
    (an average's weights in any order). *)

val transform : Transform.t -> modifier
val pattern_mod : (Pattern.t -> Pattern.t) -> modifier
val turbulence : Vec3.t -> modifier

val turb_mod : (Pattern.turbulence -> Pattern.turbulence) -> modifier
(** A change to the classic turbulence (octaves, omega, lambda), made of
    amount 0 when there is none yet, as POV-Ray's Check_Turb. *)

val check_black_hole : Loc.t -> Pattern.warp_kind -> Pattern.warp_kind
(** POV-Ray's check of a black hole once its repeat or turbulence is
    read: on each repeated axis the centre raised to the radius if below
    it, the repeat widened (with a warning) to centre + radius +
    turbulence if narrower. *)

val map : (float * Pigment.t) list -> modifier
val kind_mod : (Pattern.kind -> Pattern.kind) -> modifier

val metric : float -> modifier
(** [metric M]: facets' metric, or crackle's (other patterns ignore it). *)

val density_file : Loc.t -> string -> Pattern.kind
(** [density_file df3 "file"]: the file read (located errors when it is
    missing or damaged). *)

(** What follows an image_map's file: a change of every pixel ([once],
    [filter all A], ...), or POV-Ray's [filter N, A] / [transmit N, A],
    the filter or transmit of the palette's entry [N] (its number as
    written, taken as POV-Ray does: [int (N + 0.01)]). *)
type image_mod =
  | Every of (Pigment.image -> Pigment.image)
  | Entry of { loc : Loc.t; channel : [ `Filter | `Transmit ]; entry : float; amount : float }

val image_map : Loc.t -> ?file_gamma:float -> gamma_decode:bool -> string -> image_mod list -> Pigment.t
(** Read a PNG (beside the scene or on the include path) into an image
    map: values c^[file_gamma] when the scene gives the file's gamma,
    else decoded from sRGB when [gamma_decode]; the changes applied in
    order. Errors are located: a palette entry on an image without a
    palette, or past the palette's end, is one. *)

val image_pattern :
  Loc.t ->
  ?file_gamma:float ->
  alpha:bool ->
  interpolate:int ->
  once:bool ->
  map_type:int ->
  string ->
  Pattern.kind
(** [image_pattern { png FILE [gamma G] ... }]: the pattern of the
    image's greys, or with [alpha] ([use_alpha]) its transparency (1 -
    alpha; the red channel of an image without alpha), each pixel's
    values taken as they are in the file (POV-Ray does not gamma-correct
    image patterns), or as c^G with the file's gamma. Errors are
    located. *)

val material_map : Loc.t -> string -> once:bool -> count:int -> Pattern.kind
(** [texture { material_map { png FILE [once] TEXTURE... } }]: the
    pattern choosing one of [count] textures by the image's palette index
    or red byte. Errors are located. *)

val slope_map : Loc.t -> (float * float * float) list -> modifier
(** A normal's [slope_map { [value, <height, slope>] ... }]. *)

val warp : Loc.t -> Pattern.warp_kind -> modifier
(** [warp { ... }]: after the pattern's transformations so far. *)

val accuracy : Loc.t -> float -> modifier
(** A normal's [accuracy] (positive). *)
