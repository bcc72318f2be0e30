(** Source locations: a file and a span of positions. *)

type t = { file : string; start : Lexing.position; stop : Lexing.position }

val make : Lexing.position -> Lexing.position -> t
val none : t
val line : t -> int
val col : t -> int
(** 1-based column of the start. *)

val to_string : t -> string
(** [file:line:col] *)
