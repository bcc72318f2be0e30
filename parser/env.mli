(** The symbol table: global declarations and a stack of local scopes
    (one per include file and per macro call), as POV-Ray's [#declare] and
    [#local] see them. *)

type macro = {
  name : string;
  params : string list;
  body : Lexer.token array;  (** the tokens between the header and [#end] *)
  file : string;  (** where the macro was defined, for [#include] lookups *)
  mloc : Loc.t;
}

type binding =
  | Decl of Decl.t
  | Macro of macro
  | Array of binding option array
      (** an array (elements [None] until assigned); multi-dimensional
          arrays are arrays of arrays *)

type t

val create : unit -> t
val find : t -> string -> binding option
(** Innermost scope first, then the globals. *)

val declare : t -> string -> binding -> unit
(** [#declare]: the innermost scope that already has the name, else the
    global table. *)

val local : t -> string -> binding -> unit
(** [#local]: the innermost scope (the global table at top level). *)

val undef : t -> string -> unit
val push_scope : t -> unit
val pop_scope : t -> unit
val names : t -> string list
(** Every visible name (for "did you mean" suggestions). *)
