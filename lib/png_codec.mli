(** PNG byte streams (RFC 2083, zlib RFC 1950/1951): camlray's own
    encoder of 8-bit RGB images, and the checks a file passes before
    camlimages decodes it. Files themselves are {!Image}'s. *)

type par = int -> (int -> unit) -> unit
(** [par n f] runs [f 0] ... [f (n-1)] in any order, perhaps at once on
    several domains ([Render.parallel]). *)

val sequential : par
(** Runs them in turn. *)

val band_rows : int
(** 64: the encoder filters and compresses its rows in bands of this
    many, fixed, so that the file does not depend on [par]. *)

val bands : int -> int
(** How many bands an image of that height has. *)

val signature : string
(** The 8 bytes every PNG file starts with. *)

val encode : ?par:par -> ?text:(string * string) list -> int -> int -> Bytes.t -> string
(** [encode w h data]: a non-interlaced 8-bit RGB PNG of [w] x [h]
    pixels, [data] holding 3 bytes a pixel, row by row; [text] becomes
    tEXt chunks (key, value). Each scanline gets the filter with the
    smallest sum of absolute residuals; the scanlines are filtered and
    compressed (zlib level 6) in bands of 64 rows, each band its own
    deflate run ending in a sync flush (bands in parallel under [par]),
    so the bytes do not depend on [par]. Raises [Invalid_argument] for a
    keyword that is empty, longer than 79 bytes or contains NUL, or a
    value with NUL. *)

val adler32 : string -> int -> int -> int
(** [adler32 s pos len]: the Adler-32 checksum of RFC 1950. *)

val adler32_combine : int -> int -> int -> int
(** [adler32_combine a b len_b]: the checksum of a concatenation from the
    checksums of its parts. *)

val text : string -> (string * string) list
(** The tEXt chunks of a PNG, in order, as raw (Latin-1) bytes. Raises
    [Failure] if it is not a well-formed PNG (signature, chunk lengths,
    CRCs, an IEND). *)

val chunk : string -> string -> string option
(** [chunk s typ]: the data of the PNG [s]'s first chunk of type [typ]
    (before IEND), if any. Raises [Failure] as {!text}. *)

val check : string -> int
(** Checks everything libpng could fail on while decoding the pixels
    (camlimages' reader crashes then): chunk structure and CRCs, IHDR,
    known critical chunks, contiguous IDATs, the zlib stream, its exact
    length and the row filter bytes. Returns the colour type; raises
    [Failure] with the reason. *)
