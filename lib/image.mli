(** Images: a linear floating-point RGB frame buffer, its 8-bit encodings,
    and their files (PNG, PPM, PFM; atomic writes). PNG bytes are
    {!Png_codec}'s; comparing renders is {!Metrics}'. *)

type t
(** A [width] x [height] image of linear RGB floats, row 0 at the top. *)

val create : int -> int -> t
(** [create w h] is a black image. Requires [w > 0] and [h > 0]. *)

val create_unset : int -> int -> t
(** An image whose pixels are unspecified until set: for a caller that
    sets every one (the frame buffer of a render). *)

val width : t -> int
val height : t -> int

val set : t -> int -> int -> float -> float -> float -> unit
(** [set img x y r g b] stores a linear colour at column [x], row [y]. *)

val get_r : t -> int -> int -> float
val get_g : t -> int -> int -> float
val get_b : t -> int -> int -> float

(** {1 8-bit images} *)

type rgb8 = { w : int; h : int; data : Bytes.t }
(** Packed 8-bit RGB, row-major, 3 bytes per pixel, row 0 at the top. *)

type encoding =
  | Srgb  (** the sRGB transfer curve (POV-Ray 3.7's default File_Gamma) *)
  | Gamma_srgb of float
      (** [assumed_gamma g], g <> 1: values are taken as gamma-[g] encoded,
          decoded ([x^g]) and sRGB-encoded (checked with povray 3.7, any
          #version: 0.7 with g = 2.2 is written as 0.70578) *)
  | Identity  (** values written as they are (POV-Ray without #version 3.7) *)

val srgb_encode : float -> float
(** The sRGB opto-electronic transfer function on [0,1]. *)

type par = Png_codec.par
(** [par n f] runs [f 0] ... [f (n-1)] in any order, perhaps at once on
    several domains ([Render.parallel]); the encoders below cut their work
    into parts of fixed size, so their output does not depend on it. *)

val sequential : par

val check_rgb8 : string -> rgb8 -> unit
(** [check_rgb8 fn im] raises [Invalid_argument "fn: malformed rgb8
    image"] unless [im]'s size is positive and its bytes are 3 a pixel. *)

val quantize : encoding -> float -> int
(** The 8-bit value of one channel by the formula: clip to [0,1] (NaN
    becomes 0), encode, round to nearest. *)

type quantizer
(** {!quantize} of one encoding, by table (see {!to_rgb8}). *)

val quantizer : encoding -> quantizer

val create_rgb8 : int -> int -> rgb8
(** [create_rgb8 w h] is an 8-bit image whose pixels are unspecified until
    set. Requires [w > 0] and [h > 0]. *)

val set_rgb8 : quantizer -> rgb8 -> int -> int -> float -> float -> float -> unit
(** [set_rgb8 q im x y r g b] stores the 8-bit values of a linear colour
    at column [x], row [y]: the bytes {!to_rgb8} would give it. *)

val to_rgb8 : ?par:par -> encoding -> t -> rgb8
(** [quantize] of every channel (by a table of the 255 thresholds between
    8-bit values, equal to the formula for every float). *)

(** {1 Files} *)

val write_atomic : string -> (out_channel -> unit) -> unit
(** [write_atomic path f] writes through a temporary file in the same folder
    and renames it onto [path] only when [f] and the flush succeeded, so
    [path] never holds a truncated file. Raises [Sys_error] or [Failure]
    with a readable message naming [path] otherwise (the temporary file,
    [.NAME.XXXXXX.tmp] beside [path], is removed); other exceptions raised
    by [f] pass through unchanged. *)

val write_png : ?par:par -> ?text:(string * string) list -> string -> rgb8 -> unit
(** Non-interlaced 8-bit RGB PNG ({!Png_codec.encode}), written
    atomically; [text] becomes tEXt chunks (key, value). Raises
    [Invalid_argument] for a keyword that is empty, longer than 79 bytes or
    contains NUL, or a value with NUL, before the file is touched. *)

val write_ppm : string -> rgb8 -> unit
(** Binary PPM (P6), written atomically. *)

val write_pfm : string -> t -> unit
(** Little-endian colour PFM ("PF", scale -1.0) of the linear values,
    bottom row first as the format requires; written atomically. *)

val read_indices : string -> (int * int * Bytes.t) option
(** A palette PNG's or a GIF's size and pixel indices, one byte a pixel,
    row by row from the top; [None] for any other image. Raises [Failure] as
    {!read}. *)

val read_palette : string -> (int * int * Bytes.t * int) option
(** {!read_indices} and the number of colours the palette holds, the file
    read and decoded once. Raises [Failure] as {!read}. *)

val read_alpha : string -> Bytes.t option
(** The alpha of each pixel (one byte a pixel, row by row from the top)
    of a PNG with an alpha channel (grey or colour) or a palette (from
    its tRNS chunk, 255 for indices past it or without one); [None] for
    other PNGs (a tRNS colour key is not read) and PPMs. The pixels are
    those {!read} gives. Raises [Failure] as {!read}. *)

val is_jpeg : string -> bool
(** Whether a file's contents start as a JPEG's. *)

val jpeg_components : string -> int
(** A JPEG's colour components (1 grey, 3 colour), read from the file's
    contents. Raises [Failure] when it has no frame header. *)

val is_gif : string -> bool
(** Whether a file's contents start as a GIF's. *)

val read_gif : string -> rgb8
(** Read a GIF file's first image (libgif through camlimages). Raises
    [Failure] naming the file on error. *)

val gif_indices : string -> int * int * Bytes.t * int
(** A GIF's first image: its size, each pixel's palette index (one byte
    a pixel, row by row from the top) and its palette's size. Raises
    [Failure] naming the file on error. *)

val read_jpeg : string -> rgb8
(** Read a JPEG file (libjpeg through camlimages; grey as r = g = b).
    Raises [Failure] naming the file on error. *)

val read : string -> rgb8
(** Read a PNG (any colour type camlimages reads; alpha dropped), a JPEG
    (decoded by libjpeg through camlimages; grey as r = g = b) or a PPM
    (P6 or P3, maxval up to 65535, scaled to 8 bits), told apart by their
    first bytes. A PNG's chunks, CRCs and compressed data are checked before
    camlimages decodes it. Raises [Failure] with a message naming the file
    on error. *)

val png_text : string -> (string * string) list
(** The tEXt chunks of a PNG file, in file order, as raw (Latin-1) bytes.
    Raises [Failure] naming the file if it is not a well-formed PNG. *)

val pnm : string -> max_pixels:int -> int * int * int * int * (int -> int)
(** [pnm contents ~max_pixels]: a PNM file's (P2, P3, P5, P6) width,
    height, samples per pixel (1 or 3), maxval, and its [i]th sample (text
    samples are read in order: ask for them in order). Raises [Failure]
    on a bad header, a size beyond [max_pixels] or truncated data. *)
