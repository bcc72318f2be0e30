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
  spp : int option;  (** [None]: 64 in mc mode *)
  depth : int option;
  domains : int option;
  seed : int;
  quiet : bool;
  include_dirs : string list;
  allow_read : string list;
  region : string option;  (** ["X0,Y0,X1,Y1"] *)
  pov_region : string option;  (** POV-Ray's +SR,+ER,+SC,+EC *)
  frames : (int * int) option;  (** an animation's first and last frame *)
  clock : float option;  (** the clock of a single frame *)
  clock_range : (float * float) option;  (** clock at the first and last frame *)
  subset : (int * int) option;  (** render only these frames of [frames] *)
  tile_order_seed : int option;  (** test hook: shuffle the tile order *)
  aa : float option;  (** anti-aliasing threshold (POV-Ray's +A); whitted mode *)
  aa_depth : int;  (** POV-Ray's +R *)
  limits : Camlray_lang.Supplier.limits;  (** loop, macro-depth and token caps *)
}

val render : render_opts -> int

val with_time_limit : float option -> (unit -> 'a) -> 'a
(** [with_time_limit (Some s) f]: [f ()], a {!render} inside it cancelled
    (exit code 130, nothing written) once [s] seconds have passed. *)

val check :
  string -> string list -> string list -> Camlray_lang.Supplier.limits -> int -> float -> int
(** [check scene include_dirs allow_read limits frame_number clock] *)

val merge : string list -> string -> int
(** [merge parts out]: assemble partial renders. *)

val frame_name : string -> first:int -> last:int -> int -> string
(** POV-Ray's animation file names: [frame_name "s.png" ~first:1 ~last:12 3]
    is ["s03.png"] (the frame number padded to the digits of the last
    frame). *)
