(** Expression values of the scene language: floats, vectors of 2 to 5
    components (colours are 5-vectors: red, green, blue, filter,
    transmit) and strings, with POV-Ray's operators and built-in
    functions. Errors raise {!Diag.Error} at the given location. *)

type t = Float of float | Vector of float array | String of string

val to_string : t -> string
val type_name : t -> string

val to_float : Loc.t -> t -> float
val to_vec3 : Loc.t -> t -> Camlray.Vec3.t
(** A float is promoted to [<f,f,f>]; 2-vectors get z = 0; extra
    components are dropped. *)

val to_color : Loc.t -> t -> Camlray.Color.rgbft
(** A float sets all five channels (POV-Ray's rule for a bare [color
    0.5]); a 3-vector has filter = transmit = 0. *)

val to_rgb : Loc.t -> t -> Camlray.Color.t
val to_vec5 : t -> float array
(** Promote to 5 components (a float fills all five). *)

val to_int : Loc.t -> t -> int
val to_bool : Loc.t -> t -> bool
val to_string_value : Loc.t -> t -> string

val binop : Loc.t -> string -> t -> t -> t
(** [+ - * /] component-wise with float promotion; [< <= = != >= >]
    (floats; [=] within 1e-10); [& |] (floats as booleans). *)

val neg : Loc.t -> t -> t
val not_ : Loc.t -> t -> t
val dot_member : Loc.t -> t -> string -> t
(** [.x .y .z .t .u .v .red .green .blue .filter .transmit .gray .hf]. *)

val call : Loc.t -> string -> t list -> t
(** Built-in functions: [sin cos tan asin acos atan atan2 sqrt pow exp log
    (base 10) ln abs min max mod int floor ceil div radians degrees select
    vlength vnormalize vcross vdot vrotate vaxis_rotate vturbulence]
    (vturbulence POV-Ray's DTurbulence, with its noise)...
    Unknown names raise an error naming the function. *)

val functions : string list
(** The names {!call} knows. *)

val reset_streams : unit -> unit
(** Forget the random streams of [seed()] (a new parse starts). *)

val is_function : string -> bool
(** Whether [call] knows this name. *)

val working_gamma : float ref
(** global_settings' [assumed_gamma] as read so far (1 until one is
    given; {!Defaults.reset} puts 1 back): POV-Ray 3.7 carries sRGB
    colours and image files' colours into that gamma's space. *)

val to_working : float -> float
(** A linear value carried into the working gamma's space ([c^(1/g)]). *)

val srgb_decode : float -> float
(** An sRGB-encoded value, decoded and carried into the working gamma's
    space. *)

val rgb_kind : Loc.t -> string -> t -> t
(** [rgb_kind loc kw v]: the colour written [kw v] for [kw] one of rgb,
    rgbf, rgbt, rgbft, srgb, srgbf, srgbt, srgbft. *)

val set_channel : Loc.t -> t -> string -> float -> t
(** [color ... red 0.5]: set one channel of a colour. *)
