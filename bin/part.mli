(** Partial renders for render farms: a rectangle of the full image,
    written as a PNG that records its placement, the full size and the
    identity of the render (scene files and options), and their merge. *)

type meta = { region : Camlray.Render.tile; width : int; height : int; id : string }

val parse_region : string -> (Camlray.Render.tile, string) result
(** ["X0,Y0,X1,Y1"]: 0-based, half-open. *)

val of_pov : width:int -> height:int -> string -> (Camlray.Render.tile, string) result
(** POV-Ray's [+SR +ER +SC +EC] as ["SR,ER,SC,EC"] (empty fields absent):
    1-based and inclusive, or fractions of the image below 1. *)

val check_region : width:int -> height:int -> Camlray.Render.tile -> (unit, string) result

val text : meta -> (string * string) list
(** The PNG text chunks recording [meta]. *)

val of_text : (string * string) list -> meta option

val merge : string list -> string -> (unit, string) result
(** [merge parts out] assembles parts into the full image at [out]
    (written atomically). Refuses parts of different renders or sizes,
    gaps and overlaps, naming the parts and pixels concerned. *)
