(** The symbol table: global declarations and a stack of local scopes
    (one per include file and per macro call), as POV-Ray's [#declare] and
    [#local] see them. *)

type macro = {
  name : string;
  params : string list;
  body : Toks.t;  (** the tokens between the header and [#end], made once: every call reads them *)
  file : string;  (** where the macro was defined, for [#include] lookups *)
  mloc : Loc.t;
}

type binding =
  | Decl of Decl.t
  | Macro of macro
  | Array of binding option array
      (** an array (elements [None] until assigned); multi-dimensional
          arrays are arrays of arrays *)
  | Unsupported of unsupported
      (** a [#declare] whose right-hand side uses something camlray cannot
          parse yet: the error is reported only when the name is used *)

and unsupported = {
  feature : string;  (** the POV-Ray word camlray does not know, e.g. [marble] *)
  feature_loc : Loc.t;  (** where that word stands *)
  declared : Loc.t;  (** where the name was declared *)
  failure : string option;
      (** [Some msg]: not an unknown word but an error in a [#declare] of an
          include file (e.g. syntax camlray's grammar does not cover yet),
          reported, with [feature_loc], only when the name is used *)
}

type t

val create : unit -> t
val find : t -> string -> binding option
(** Innermost scope first, then the globals. *)

type cell
(** Where a name's binding is kept: declaring the name again rewrites
    the cell. *)

val lookup : t -> string -> cell option
(** The cell {!find} reads. *)

val binding : cell -> binding

val generation : t -> int
(** Moves whenever a name is added or removed or a scope is entered or
    left: while it stays, every name's {!lookup} gives the same cell. *)

val declare : t -> string -> binding -> unit
(** [#declare]: the innermost scope that already has the name, else the
    global table. *)

val local : t -> string -> binding -> unit
(** [#local]: the innermost scope (the global table at top level). *)

val undef : t -> string -> unit
val push_scope : t -> unit
val pop_scope : t -> unit

type mark

val mark : t -> mark
(** The current scope stack, to return to after an aborted sub-parse. *)

val restore : t -> mark -> unit

val local_at : t -> mark -> string -> binding -> unit
val declare_at : t -> mark -> string -> binding -> unit
(** {!local} and {!declare} as seen from the scopes of a {!mark}: a
    directive binds in the scope where it was written, even when the
    value it reads ends inside a macro's body (a macro that returns
    [Q;]). *)
val names : t -> string list
(** Every visible name (for "did you mean" suggestions). *)
