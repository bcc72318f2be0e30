(** Diagnostics: the one error type of the scene language and its one
    printer, [FILE:LINE:COL: error: MESSAGE], the source line and a caret,
    then the chain of includes and macro calls that led there. *)

type t = { loc : Loc.t; msg : string; chain : (string * Loc.t) list }
(** [chain]: innermost first, e.g. [("included from", loc)]. *)

exception Error of t

val error : ?chain:(string * Loc.t) list -> Loc.t -> ('a, unit, string, 'b) format4 -> 'a
(** Raise [Error] with a formatted message. *)

val warning : Loc.t -> string -> unit
(** Print [FILE:LINE:COL: warning: MSG] on stderr (with the source line). *)

val collect_warnings : (unit -> 'a) -> 'a * string
(** [f ()] with the warnings it gives collected (as they would be printed)
    instead of printed: for tests. Not for use from several domains at
    once. *)

val to_string : t -> string
(** The full report, ending with a newline. *)

val register_source : string -> string -> unit
(** Remember a file's text so that reports can quote its lines. *)
