(** The token supplier's state: a stack of token cursors (the scene, its
    included files, macro bodies), the control structures open in each,
    the symbol table and the open data files, with the raw-token
    primitives shared by the directive modules ({!Control}, {!Macros},
    {!Arrays}, {!Dataio}) and {!Supplier}. Internal to the scene
    language. *)

open Lexer

type limits = {
  max_loop_iterations : int;
  max_macro_depth : int;
  max_include_depth : int;
  max_array_size : int;
  max_tokens : int;  (** raw tokens read in all, loops and macros included *)
  max_objects : int;  (** objects read or placed, see {!Budget} *)
}

val default_limits : limits

type config = {
  include_dirs : string list;
  limits : limits;
  builtins : (string * float) list;
  access : Access.t;  (** what the scene may read and write *)
  fold : bool;
      (** fold arithmetic runs before the parser sees them ({!Fold}); the
          scene reads the same either way (off to test that) *)
  quick : bool;
      (** evaluate plain expressions of directives without the parser
          ({!Quick}); the scene reads the same either way (off to test
          that) *)
}

(* Open control structures of one frame, innermost first. *)
type ctrl =
  | In_if of Loc.t  (** executing a taken branch of #if/#ifdef/#ifndef *)
  | In_while of { cond_pos : int; mutable count : int; wloc : Loc.t }
  | In_for of {
      var : string; stop : float; step : float; body_pos : int; mutable count : int; floc : Loc.t }
  | In_switch of Loc.t  (** executing a matched clause *)

val opener : ctrl -> string * Loc.t
(** The directive that opened a structure and where, for messages. *)

(* A file opened by #fopen: data tokens to #read, or a channel to #write. *)
type reader = { data : token array; mutable at : int }
type handle = Reading of reader | Writing of out_channel

(* Where a macro parameter passed by reference writes back. *)
type target = Name of string | Element of Env.binding option array * int

type kind = Main | Include of Loc.t | Macro_call of string * Loc.t

type frame = {
  toks : Toks.t;
  mutable pos : int;
  kind : kind;
  file : string;
  mutable ctrl : ctrl list;
  scoped : bool;
  byref : (string * target) list;
      (** macro parameters given a bare identifier, with that identifier:
          their final values are copied back when the macro ends
          (POV-Ray passes identifiers by reference) *)
}

(* Runs a sub-parse from an entry point; set by Supplier.create. *)
type runner = { run : 'a. (Lexing.position -> 'a Parser.MenhirInterpreter.checkpoint) -> 'a }

type t = {
  config : config;
  builtins : float Words.t;  (** [config.builtins] as a table *)
  mutable runner : runner;
  env : Env.t;
  mutable frames : frame list;
  mutable pending : (Parser.token * Loc.t) list;  (** pushed-back tokens *)
  mutable last : Loc.t;
  mutable files : string list;
  handles : (string, handle) Hashtbl.t;  (** #fopen'ed files by identifier *)
  mutable stop_at : (frame * int) option;
      (** hand the parser a ';' when this frame reaches this position
          (ends a value that has no terminator, see {!Splread}) *)
  mutable braces : Loc.t list;  (** the '{' not yet closed, innermost first *)
  mutable skipped : string list;  (** the blocks read past ([photons]), warned once *)
  mutable context : string option;  (** what is being parsed, for messages *)
  deprecated : (string, string * bool * bool ref) Hashtbl.t;
      (** [#declare deprecated [once] "why" NAME = ...]: warn on use *)
  mutable supplied : int;  (** raw tokens read so far, for [max_tokens] *)
  mutable depth : int;  (** parses in progress: 1 while the scene's own parse reads *)
  mutable optional_sep : Parser.token option;
      (** for the next sub-parse only: a separator that may be left out
          (array initialisers: [{ <1,2> <3,4> }]); the parser gets it
          where the next token cannot continue *)
  mutable semi_probe : (string * Loc.t) option ref option;
      (** for the next sub-parse only: where a directive (or the end of
          the file) stands in the same file where a ';' could end the
          phrase, the parser is given that ';' and the directive is
          recorded here (POV-Ray: a #declare missing its ';') *)
}

val create : config -> Env.t -> file:string -> Toks.t -> t
(** A supplier state on a file's tokens; its [runner] is set by
    {!Supplier.create}. *)

val files_read : t -> string list

val builtin : t -> string -> float option
(** The value of a built-in identifier ([clock], [image_width], ...). *)
val parse : t -> (Lexing.position -> 'a Parser.MenhirInterpreter.checkpoint) -> 'a
(** A sub-parse from an entry point, through [t.runner]. *)

val chain : t -> (string * Loc.t) list
(** The include/macro chain of the current position, innermost first. *)

val fail : t -> Loc.t -> ('a, unit, string, 'b) format4 -> 'a
(** Raise a located error carrying the current chain. *)

exception Unsupported_use of Diag.t * Env.unsupported
(** Raised where a POV-Ray word camlray does not know (or a name bound to
    such a #declare) is met: a [#declare] catches it and binds its name to
    an {!Env.Unsupported} marker; anywhere else it becomes the error. *)

val unsupported :
  t -> Loc.t -> Env.unsupported -> ('a, unit, string, 'b) format4 -> 'a
(** Raise {!Unsupported_use} with a located message. *)

val unsupported_name : t -> string -> Env.unsupported -> Loc.t -> 'a
(** A name bound to a marker is used: raise {!Unsupported_use}. *)

val skip_phrase : t -> unit
(** Skip the rest of a phrase of the current frame: to a ';' at depth 0
    (included), a directive or an unmatched closing bracket. *)

val top : t -> frame
val raw_next : t -> token
(** The next raw token, leaving finished included files and macro bodies
    (restoring scopes, #version and by-reference arguments). Raises when
    a frame ends with a structure still open. *)

val raw_peek : t -> token

val peek_past_ends : t -> from:frame -> token
(** The next raw token, first leaving the finished frames above [from]
    (a macro called at the end of a #declare's value), so that a ';'
    after the call is seen. *)
val expect_raw : t -> string -> (raw -> bool) -> token
val expect_tok : t -> Parser.token -> string -> unit
val expect_ident : t -> string -> string * Loc.t

val skip_block : t -> stop:string list -> string * token
(** Skip to the directive ending the current block at depth 0 ([#end],
    or one of [stop]); returns its name and token. *)

val candidates : t -> string -> string list
(** Where [#include] and [file_exists] look for a name, in order. *)

val allowed : t -> Loc.t -> string -> unit
(** Fail, located, unless the scene may read or write [path] ({!Access}). *)

val find_file : t -> string -> string option
