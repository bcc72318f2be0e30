(** The scene language's only entry point: read a file (or a string) into
    an evaluated scene description. Never raises: every failure is a
    located {!Diag.t}. *)

type options = {
  include_dirs : string list;
      (** searched for [#include] after the current folder and the scene's
          folder; POV-Ray's include folder is appended when it exists *)
  limits : Supplier.limits;
  clock : float;
  image_width : int;
  image_height : int;
  frame_number : int;
  allow_read : string list;
      (** folders a scene may read besides the include search folders *)
  confine_reads : bool;
      (** confine reads to those folders (default [true]; see {!Access}) *)
  fold_arithmetic : bool;
      (** fold runs of float arithmetic before the parser (default [true];
          see {!Fold}): the scene is the same either way, only read faster *)
  quick_eval : bool;
      (** evaluate the plain expressions of directives ([#declare X = ...;],
          [#if (...)], [#while (...)], [#write] items, macro arguments,
          array indices) without the parser (default [true]; see
          {!Quick}): the scene is the same either way, only read faster *)
}

val default_options : options

val pov_include_dir : string
(** /usr/share/povray-3.7/include *)

val file : ?options:options -> string -> (Sdl.scene * string list, Diag.t) result
(** The scene and every file it read (the scene and its includes). *)

val string : ?options:options -> ?name:string -> string -> (Sdl.scene, Diag.t) result
(** Parse scene text; [name] (default ["<string>"]) is used in messages and
    as the scene's folder for includes (the current folder). *)
