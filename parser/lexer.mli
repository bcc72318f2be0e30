(** The sedlex lexer: turns a whole file (UTF-8) into an array of located
    raw tokens, once. Keywords become parser tokens; identifiers stay
    names until the supplier types them; [#word] becomes a directive. *)

type raw =
  | Tok of Parser.token
  | Ident of string
  | Directive of string  (** [#declare] is [Directive "declare"] *)
  | Eof

type token = { raw : raw; loc : Loc.t }

module Words : Hashtbl.S with type key = string
(** Tables keyed by names (keywords, built-in identifiers). *)

val tokenize : file:string -> string -> token array
(** Raises {!Diag.Error} on a lexical error (unterminated string or
    comment, stray character). The last token is [Eof]. *)

val stream : file:string -> string -> unit -> token
(** The same tokens one at a time, lexed as they are asked for; after the
    [Eof] token, [Eof] again. Raises {!Diag.Error} when a lexical error is
    reached. *)

val describe : raw -> string
(** How a token is named in messages: ["'{'"], ["keyword sphere"],
    ["identifier Foo"], ["end of file"]. *)

val keyword_names : unit -> string list
(** Every word the lexer turns into a keyword token (for fuzzing and
    tools). *)

val pov_reserved : string -> bool
(** Whether a name is a POV-Ray 3.7 reserved word (so that an unsupported
    keyword can be reported by name). *)

val keyword_of : raw -> string option
(** The keyword a token stands for, if it is one. *)
