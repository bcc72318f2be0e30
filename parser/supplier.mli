(** The token supplier and directive evaluator. It walks a stack of token
    cursors (the main file, included files, macro bodies, loop bodies),
    evaluates POV-Ray's directives as it meets them ([#version],
    [#declare], [#local], [#undef], [#include], [#if]/[#ifdef]/[#ifndef]/
    [#elseif]/[#else], [#switch]/[#case]/[#range]/[#break], [#while],
    [#for], [#macro], [#debug]/[#warning]/[#error], [#default],
    [#fopen]/[#read]/[#write]/[#fclose]) and hands the parser identifiers
    typed by what they are bound to; [function { ... }] bodies are read
    here and compiled by {!Fnparse}. Sub-parses (a [#declare]'s right-hand
    side, a condition) pull tokens from the same supplier, so directives
    nest anywhere. The state and the directive groups live in {!Cursor},
    {!Control}, {!Macros}, {!Arrays} and {!Dataio}; this module types
    identifiers, drives menhir and dispatches directives. *)

type limits = {
  max_loop_iterations : int;  (** per [#while]/[#for] loop *)
  max_macro_depth : int;
  max_include_depth : int;
  max_array_size : int;
  max_tokens : int;  (** raw tokens read in all, loops and macros included *)
  max_objects : int;  (** objects read or placed, see {!Budget} *)
}

val default_limits : limits

type config = {
  include_dirs : string list;
      (** folders searched, in order, for [#include] (after the current
          folder and the scene's folder) *)
  limits : limits;
  builtins : (string * float) list;
  access : Access.t;  (** what #include may read *)
  fold : bool;  (** fold arithmetic runs first ({!Fold}); the same scene either way *)
  quick : bool;
      (** plain expressions of directives evaluated without the parser
          ({!Quick}); the same scene either way *)
      (** [clock], [image_width], [image_height], [frame_number], ... *)
}

type t

val create : config -> Env.t -> file:string -> Toks.t -> t

val parse : t -> (Lexing.position -> 'a Parser.MenhirInterpreter.checkpoint) -> 'a
(** Run a (sub-)parse from an entry point of the grammar, pulling tokens
    from the supplier. Raises {!Diag.Error} with a located message naming
    what was expected and what was found. *)

val close_files : t -> unit
(** Close the files that [#fopen] left open (call at the end of a parse). *)

val files_read : t -> string list
(** Every file read so far (the scene and its includes), absolute paths. *)

val find_readable : t -> Loc.t -> string -> string option
(** A file the scene names, found as an include file is (the current
    folder, the scene's, the include path), when the scene may read it
    (a located error otherwise). *)
