(** The parallel pixel loop: the only module that knows about domains.
    The image is cut into fixed square tiles in absolute image coordinates;
    a domainslib pool of [domains] workers takes tiles with
    [Task.parallel_for]; each tile writes only its own pixels. Output does
    not depend on the domain count or on which worker took which tile. *)

type tile = { x0 : int; y0 : int; x1 : int; y1 : int }
(** Half-open pixel rectangle [[x0, x1) x [y0, y1)]. *)

val tiles : width:int -> height:int -> size:int -> tile array
(** The tiles of an image, in row-major order. *)

val run_tiles :
  domains:int -> ?progress:(done_:int -> total:int -> unit) ->
  ?cancelled:(unit -> bool) -> ?order_seed:int -> width:int -> height:int -> size:int ->
  (tile -> unit) -> unit
(** Run [f] on every tile. [progress] is called after tiles complete (from
    one domain at a time, possibly not for every tile). When [cancelled ()]
    becomes true, remaining tiles are skipped and [Cancelled] is raised.
    The pool is torn down whatever happens. [order_seed] shuffles the order
    in which tiles are handed out (a test hook: images must not depend on
    it). *)

exception Cancelled

val image :
  domains:int -> ?progress:(done_:int -> total:int -> unit) ->
  ?cancelled:(unit -> bool) -> ?order_seed:int -> ?region:tile -> width:int -> height:int ->
  (int -> int -> Color.t) -> Image.t
(** Evaluate a pixel function [f x y] over the whole image in 16x16 tiles
    ([x], [y] in full-image coordinates). With [region], only that
    rectangle is rendered, into an image of the region's size; the tiles
    stay aligned to the full image, so every pixel is computed exactly as
    in a full render. [cancelled] is also checked between pixels. *)

val image_into :
  domains:int -> ?progress:(done_:int -> total:int -> unit) ->
  ?cancelled:(unit -> bool) -> ?order_seed:int -> ?region:tile -> width:int -> height:int ->
  (int -> int -> Color.acc -> unit) -> Image.t
(** {!image} with a pixel function that writes its colour into a sum
    (one per tile, overwritten at every pixel): no colour record per
    pixel. *)

val rgb8_into :
  domains:int -> ?progress:(done_:int -> total:int -> unit) ->
  ?cancelled:(unit -> bool) -> ?order_seed:int -> ?region:tile -> width:int -> height:int ->
  Image.encoding -> (int -> int -> Color.acc -> unit) -> Image.rgb8
(** {!image_into} quantized as the pixels are made: the bytes
    [Image.to_rgb8 encoding (image_into ...)] holds, without the frame of
    floats (24 bytes a pixel, 3 here). *)

val with_pool : domains:int -> (unit -> 'a) -> 'a
(** [with_pool ~domains f] runs [f] with one pool of [domains] workers set
    up for it (with more domains than cores, at the first parallel loop,
    so that the parse runs without it): the parallel loops [f] starts with
    the same domain count (tiles, {!parallel}) run on that pool instead of
    setting up their own, and its workers stay ready between them. The
    pool is torn down when [f] returns or raises. Inside another
    [with_pool], or with [domains <= 1], it just runs [f]. *)

val parallel : domains:int -> Image.par
(** [parallel ~domains n f] runs [f 0] ... [f (n-1)] on a pool of
    [domains] workers, the {!with_pool} pool when there is one (in turn
    when [domains <= 1]): the image encoders' parts, the BVH's subtrees. *)

val pulled : domains:int -> Image.par
(** [pulled ~domains n f] runs [f 0] ... [f (n-1)] as {!parallel} does,
    each domain taking the next [i] from a shared counter until none is
    left: for many small items of uneven cost (radiosity's samples),
    where a task of [parallel]'s per item would cost as much as the
    item. *)
