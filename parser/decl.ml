type t =
  | Value of Value.t
  | Object of Sdl.obj
  | Pigment of Camlray.Pigment.t
  | Finish of Camlray.Finish.t
  | Texture of Camlray.Texture.t
  | Interior of Camlray.Interior.t
  | Transform of Camlray.Transform.t
  | Camera of Sdl.camera_item list
  | Function of Fn.t
  | Spline of Spline.t
  | Color_map of (float * Camlray.Pigment.t) array
  | Normal of Camlray.Normal.t option
  | Material of (Camlray.Texture.t option * Camlray.Interior.t option)
  | Sky_sphere of Camlray.Sky.t
  | Media of Camlray.Media.t  (** [media { ... }] *)
  | Density of Camlray.Pigment.t  (** [density { ... }]: a density is a pigment's pattern of values *)

let kind_name = function
  | Value v -> Value.type_name v
  | Object _ -> "an object"
  | Pigment _ -> "a pigment"
  | Finish _ -> "a finish"
  | Texture _ -> "a texture"
  | Interior _ -> "an interior"
  | Transform _ -> "a transform"
  | Camera _ -> "a camera"
  | Function _ -> "a function"
  | Spline _ -> "a spline"
  | Color_map _ -> "a colour map"
  | Normal _ -> "a normal"
  | Material _ -> "a material"
  | Sky_sphere _ -> "a sky_sphere"
  | Media _ -> "a media"
  | Density _ -> "a density"
