(** TrueType fonts, as far as POV-Ray's [text] reads them: the outlines
    of glyphs (quadratic B-spline contours, composite glyphs assembled),
    their horizontal metrics, horizontal kerning pairs and the character
    map. Outlines are in font units (y up). *)

type segment =
  | Line of float * float * float * float  (** x0, y0, x1, y1 *)
  | Quad of float * float * float * float * float * float
      (** x0, y0, control x, y, x1, y1 *)

type glyph = {
  contours : segment array array;  (** each contour closed *)
  xmin : float;  (** the glyph header's box *)
  ymin : float;
  xmax : float;
  ymax : float;
}

type t

val parse : string -> t
(** The font in a file's bytes. Raises [Failure] with a message when they
    are not a TrueType font camlray can read (a missing table, an index
    out of range, a truncated table). *)

val read : string -> t
(** {!parse} of a file; [Failure] names the file. *)

val units_per_em : t -> int
val glyph_index : t -> int -> int
(** The glyph of a character code (POV-Ray's preference of maps for ASCII
    text: Macintosh Roman, then Windows Unicode, Unicode, Windows
    symbol); 0, the missing glyph, when none. *)

val glyph : t -> int -> glyph
val advance : t -> int -> int
(** Advance width of a glyph (the last metric for glyphs past the table). *)

val lsb : t -> int -> int
(** Left side bearing of a glyph. *)

val kerning : t -> int -> int -> int
(** [kerning f left right]: the horizontal kerning of a glyph pair (POV-Ray's
    rules: summed over horizontal tables, or the last when a table
    overrides, at least -units_per_em); 0 when none. *)
