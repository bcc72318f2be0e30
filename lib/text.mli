(** POV-Ray's [text]: a string's glyphs, set as POV-Ray sets them (em
    units, kerning, the extra [offset] after each character), extruded
    from z = 0 to z = [thickness]. Its surfaces are the glyphs' outlines
    (quadratic curves and lines) swept along z, and the faces at both
    ends; inside is inside an outline (nonzero winding) between them. *)

type t

val make_codes : Ttf.t -> int array -> thickness:float -> offset:Vec3.t -> t
(** The glyphs of these character codes (Unicode code points, as the
    font's character map reads them), set in a row. *)

val make : Ttf.t -> string -> thickness:float -> offset:Vec3.t -> t
(** [make_codes] of the string's bytes. *)

val glyph_count : t -> int
val thickness : t -> float

val bounds : t -> Vec3.t * Vec3.t

val hit_s : t -> Ray.scratch -> float -> Hit.t -> bool
(** The nearest crossing in [(tmin, h.t)] past [h.floor]; [h.id] says
    which surface (0 the front face, 1 the back, 2 + i curve i; a
    negative id would be taken for a sphere by {!Scene}) and
    [h.u] where on the curve. Allocates nothing. *)

val normal_into : t -> Hit.t -> Vec3.m -> unit
(** The outward unit normal of the surface a hit found. *)

val inside : t -> float -> float -> float -> bool

val winding : t -> float -> float -> int
(** The winding number of the outlines around a point of the glyphs'
    plane (for tests). *)
