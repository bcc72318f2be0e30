(** What a [#declare] or [#local] can bind, and what a macro argument can
    be: every kind of value the scene language names. *)

type t =
  | Value of Value.t
  | Object of Sdl.obj
  | Pigment of Camlray.Pigment.t
  | Finish of Camlray.Finish.t
  | Texture of Camlray.Texture.t
  | Interior of Camlray.Interior.t
  | Transform of Camlray.Transform.t
  | Camera of Sdl.camera_item list
  | Function of Fn.t  (** [function { ... }] *)
  | Spline of Spline.t  (** [spline { ... }] *)
  | Color_map of (float * Camlray.Pigment.t) array
  | Normal of Camlray.Normal.t option
  | Material of (Camlray.Texture.t option * Camlray.Interior.t option)
  | Sky_sphere of Camlray.Sky.t
  | Media of Camlray.Media.t  (** [media { ... }] *)
  | Density of Camlray.Pigment.t  (** [density { ... }]: a density is a pigment's pattern of values *)

val kind_name : t -> string
(** "a float", "an object", "a pigment", ... for messages. *)
