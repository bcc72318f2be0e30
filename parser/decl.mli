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
  | Material of material

(** [material { texture {...} interior {...} }]: either part may be absent. *)
and material = { mtexture : Camlray.Texture.t option; minterior : Camlray.Interior.t option }

val kind_name : t -> string
(** "a float", "an object", "a pigment", ... for messages. *)
