(** The values POV-Ray 3.7 gives a height field (0 .. 65535) from image
    pixels and functions (imageutil.cpp's image_height_at and the image
    classes' conversions, in single precision as POV-Ray computes them):
    8-bit grey [v] -> [v/255 * 65535] truncated, 16-bit grey likewise over
    65535, a palette's index times 256, 8-bit colour [(r*256 + g) * 255]
    (red the high byte, green the low one), deeper colour the grey [0.297
    r + 0.589 g + 0.114 b]. A function's value [v] is stored as
    [v * 65535] truncated to 16 bits (no clipping: 1.5 wraps to 32766, as
    POV-Ray's does). *)

type image = { w : int; h : int; v : int array  (** height values, row 0 the image's top row *) }

val read : ?pot:bool -> string -> image
(** A PNG (non-interlaced, any colour type and depth), JPEG, GIF, PGM or
    PPM (P2, P3, P5, P6) file, told apart by its first bytes; with [pot]
    a POT file (a GIF twice as wide as the field, a 16-bit height from
    its two halves' indices). Raises [Failure]. *)

val of_gray8 : int -> int
val of_gray16 : int -> int
val of_index : int -> int
val of_rgb8 : int -> int -> int
val of_rgb16 : int -> int -> int -> int

val of_float : float -> int
(** A float function's value. *)

val of_color : float -> float -> float -> int
(** A pigment function's colour. *)
