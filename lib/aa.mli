(** Anti-aliasing as POV-Ray 3.7's sampling method 1 (non-adaptive, +AM1)
    without jitter (pov-facts.md section 7). The image is traced in fixed
    32x32 blocks in absolute image coordinates; in each block, pixel
    centres are traced in scan order, together with the row above and the
    column left of the block (traced for comparison only, also at the
    image border, where they lie outside the image: POV-Ray does the same,
    checked on a cross-render). A pixel is
    compared with its left and upper neighbours on gamma-2.5 encoded
    values (|dr|+|dg|+|db| >= threshold); when they differ, the pixel and
    each differing neighbour not yet supersampled are supersampled: an
    n x n grid at offsets (k+0.5)/n - 0.5 plus the centre sample, divided
    by n^2+1. The result does not depend on the domain count or on the
    order in which blocks are taken. *)

val block : int
(** 32 *)

val encode : Color.t -> Color.t
(** Raise to 1/2.5 (the antialias gamma); values above 1 are not clipped
    (as in POV-Ray: found by cross-rendering highlights), negative ones
    count as 0. *)

val differs : float -> Color.t -> Color.t -> bool
(** [differs threshold a b] on encoded colours. *)

val supersample : depth:int -> (float -> float -> Color.t) -> int -> int -> Color.t -> Color.t
(** [supersample ~depth sample x y centre]: the supersampled value of
    pixel [(x, y)] given its centre sample. [sample px py] takes image
    coordinates (pixel [(x, y)] spans [[x, x+1) x [y, y+1)]). *)

val render :
  domains:int -> ?progress:(done_:int -> total:int -> unit) ->
  ?cancelled:(unit -> bool) -> width:int -> height:int -> threshold:float -> depth:int ->
  (float -> float -> Color.t) -> Image.t
(** Render an image with anti-aliasing; [depth] in 1..9. *)

val render_into :
  domains:int -> ?progress:(done_:int -> total:int -> unit) ->
  ?cancelled:(unit -> bool) -> width:int -> height:int -> threshold:float -> depth:int ->
  (float -> float -> Color.acc -> unit) -> Image.t
(** {!render} with a sample function that writes its colour into a sum
    (per domain, overwritten at every sample). *)
