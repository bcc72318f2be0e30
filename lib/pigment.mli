(** Pigments: the colour (with filter and transmit) of a surface point.
    A pattern pigment carries the transform from pattern space to world
    space accumulated from its own modifiers and those of the textures and
    objects written after it (POV-Ray's rule). *)

type image = {
  w : int;
  h : int;
  px : Color.rgbft array;  (** row-major, row 0 at the top, linear values *)
  once : bool;
  interpolate : int;  (** 0 none, 2 bilinear, 3 bicubic, 4 normalized distance, as POV-Ray's *)
  map_type : int;
}
(** An image map. [map_type] 0 (planar): the image covers the unit square
    of the xy plane (x to the right, y up) and repeats unless [once]; 1
    (spherical): it wraps the unit sphere, u the longitude from +x towards
    +z, v the latitude from -y to +y; 2 (cylindrical): u the same
    longitude, v the height y (repeating unless [once]). *)

type t =
  | Solid of Color.rgbft
  | Map of { pattern : Pattern.t; entries : (float * t) array; xform : Transform.t }
      (** colour_map / pigment_map: entries sorted by value; solid entries
          are colour map entries. As in POV-Ray 3.7, the entries are
          taken at the point the pattern is evaluated at, in its space
          (the pattern's transformations, warps and turbulence applied):
          their own transformations are relative to it, whatever the
          order the map and the pattern's modifiers were written in *)
  | Blocks of { pattern : Pattern.t; cells : t array; xform : Transform.t }
      (** checker, hexagon, brick with their list of colours or pigments
          (taken as a map's entries are) *)
  | Image_map of { image : image; xform : Transform.t; warp : Pattern.t option }
      (** [warp]: a pattern whose warps and turbulence move the point
          in the image's space before the image is read (its kind is
          unused), as POV-Ray 3.7 warps an image map *)
  | Average of { entries : (float * t) array; xform : Transform.t; warp : Pattern.t option }
      (** POV-Ray's [average pigment_map]: the entries' colours weighted
          (weights summing to 1), each taken at the average's own point
          (its transformations, then [warp]'s warps and turbulence,
          applied), as a map's entries are *)
  | Uv of t
      (** POV-Ray's [uv_mapping]: the pigment taken at the surface's
          [<u, v, 0>] (see {!Pattern.uv_point}) instead of the point;
          transformations applied after it leave it unchanged *)

val solid : Color.rgbft -> t
val black : t
(** POV-Ray's default pigment. *)

val default_entries : Pattern.kind -> (float * t) array
(** The colour map a pattern uses when none is given: POV-Ray's built-in
    ones (checker, hexagon, brick, bozo, radial, marble, wood, agate; read
    from POV-Ray's [function { pigment { ... } }] values), black to white
    otherwise. *)

val transform : Transform.t -> t -> t
(** Move a pigment by a transform applied after its current one: a
    map's or block pattern's own pattern (its entries follow it, being
    taken in its space), an image map, an average. Solid
    colours and uv-mapped pigments are unchanged. *)

val uv : t -> t
(** [Uv p] (a pigment already uv-mapped is kept). *)

val uses_uv : t -> bool
(** Some part of the pigment is uv-mapped: the shader must set the
    surface's uv before evaluating it. *)

val opaque : t -> bool
(** Filter and transmit are 0 everywhere. *)

val bound : t -> float
(** The largest absolute value any of the pigment's rgb channels takes
    anywhere (a colour map's or block pattern's entries, an image's
    pixels, an average's weighted entries): what the Monte Carlo mode's
    tracking through a medium's density takes as its majorant. *)

val eval : t -> Vec3.t -> Color.rgbft
(** The colour at a point in world space. *)

(** A colour written in place, flat: shading keeps one per nesting level. *)
type out = {
  mutable r : float;
  mutable g : float;
  mutable b : float;
  mutable filter : float;
  mutable transmit : float;
}

val out : unit -> out

val into : t -> Vec3.m -> out -> unit
(** [into p point o]: {!eval} at a point written in place, into [o] (the
    same arithmetic), allocating nothing (per domain, the work of nested
    maps is kept). *)


