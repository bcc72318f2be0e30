(** Images: a linear floating-point RGB frame buffer, its 8-bit encodings,
    file formats (PNG, PPM, PFM; atomic writes), and image metrics (PSNR,
    SSIM) for comparing renders. *)

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

type par = int -> (int -> unit) -> unit
(** [par n f] runs [f 0] ... [f (n-1)] in any order, perhaps at once on
    several domains ([Render.parallel]); the encoders below cut their work
    into parts of fixed size, so their output does not depend on it. *)

val sequential : par

val quantize : encoding -> float -> int
(** The 8-bit value of one channel by the formula: clip to [0,1] (NaN
    becomes 0), encode, round to nearest. *)

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
(** Non-interlaced 8-bit RGB PNG, written atomically; [text] becomes tEXt
    chunks (key, value). Raises [Invalid_argument] for a keyword that is
    empty, longer than 79 bytes or contains NUL, or a value with NUL.
    The scanlines are filtered and compressed in bands of 64 rows, each
    band its own deflate run ending in a sync flush (bands in parallel
    under [par]). *)

val adler32 : string -> int -> int -> int
(** [adler32 s pos len]: the Adler-32 checksum of RFC 1950. *)

val adler32_combine : int -> int -> int -> int
(** [adler32_combine a b len_b]: the checksum of a concatenation from the
    checksums of its parts. *)

val write_ppm : string -> rgb8 -> unit
(** Binary PPM (P6), written atomically. *)

val write_pfm : string -> t -> unit
(** Little-endian colour PFM ("PF", scale -1.0) of the linear values,
    bottom row first as the format requires; written atomically. *)

val read : string -> rgb8
(** Read a PNG (any colour type camlimages reads; alpha dropped) or a PPM
    (P6 or P3, maxval up to 65535, scaled to 8 bits), told apart by their
    first bytes. A PNG's chunks, CRCs and compressed data are checked before
    camlimages decodes it. Raises [Failure] with a message naming the file
    on error. *)

val png_text : string -> (string * string) list
(** The tEXt chunks of a PNG file, in file order, as raw (Latin-1) bytes.
    Raises [Failure] naming the file if it is not a well-formed PNG. *)

(** {1 Metrics}

    The functions taking two images raise [Invalid_argument] when their
    sizes differ. *)

val psnr : rgb8 -> rgb8 -> float
(** PSNR in dB over the R, G, B bytes; [infinity] for identical images.
    Requires equal sizes. *)

val ssim : rgb8 -> rgb8 -> float
(** Mean SSIM on the luma Y = 0.2126 R + 0.7152 G + 0.0722 B of the 8-bit
    values, Gaussian window 11x11 with sigma 1.5, K1 = 0.01, K2 = 0.03,
    L = 255, averaged over the windows that fit inside the image (as
    scikit-image's [structural_similarity] with [gaussian_weights=True],
    [use_sample_covariance=False], [data_range=255]). Requires equal sizes
    of at least 11x11. *)

val max_diff : rgb8 -> rgb8 -> int
(** Largest absolute difference of any channel. *)

val diff_image : ?gain:int -> rgb8 -> rgb8 -> rgb8
(** Per-channel absolute difference times [gain] (default 4), clipped. *)

val side_by_side : rgb8 list -> rgb8
(** The images placed left to right (heights padded with black). *)
