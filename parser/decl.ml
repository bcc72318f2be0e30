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
  | Material of material

and material = { mtexture : Camlray.Texture.t option; minterior : Camlray.Interior.t option }

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
  | Material _ -> "a material"
