(** Macros and [#include]: the directives that push a frame of tokens. *)

val define : Cursor.t -> Loc.t -> unit
(** [#macro Name(params) ... #end]: record the body's tokens. *)

val call : Cursor.t -> Env.macro -> Loc.t -> unit
(** After a macro's name: read the arguments and push the body with the
    parameters bound in a new scope. A bare declared identifier is
    passed by reference (copied back when the macro ends). *)

val include_file : Cursor.t -> Loc.t -> unit
(** [#include "file"] (depth limit, cycle check). *)
