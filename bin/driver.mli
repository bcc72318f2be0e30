(** What the commands do: load, compile, render, write; errors become
    messages and exit codes (0 ok, 1 scene/file/value error, 130
    interrupted). *)

type mode = Whitted | Monte_carlo

type render_opts = {
  scene : string option;  (** [None]: the built-in default scene *)
  output : string option;
  width : int;
  height : int;
  mode : mode;
  spp : int;
  depth : int option;
  domains : int option;
  seed : int;
  quiet : bool;
  include_dirs : string list;
  aa : float option;  (** anti-aliasing threshold ([--aa]); [None]: off *)
  aa_depth : int;  (** [--aa-depth], 1..9 *)
}

val render : render_opts -> int
val check : string -> string list -> int
