open Camlray

type shape =
  | Sphere of Vec3.t * float
  | Plane of Vec3.t * float
  | Light of light

and light = {
  position : Vec3.t;
  color : Color.t;
  kind : Light.kind;
  fade_distance : float;
  fade_power : float;
  shadowless : bool;
  area : Light.area option;
  looks_like : obj option;  (** drawn at the light's position, casts no shadow *)
}

and obj = {
  loc : Loc.t;
  shape : shape;
  xform : Transform.t;
  texture : Texture.t option;
  interior : Interior.t option;
  no_shadow : bool;
  hollow : bool;
}

type camera_item =
  | Perspective
  | Orthographic
  | Location of Vec3.t
  | Look_at of Vec3.t
  | Angle of float
  | Right of Vec3.t
  | Up of Vec3.t
  | Direction of Vec3.t
  | Sky of Vec3.t
  | Aperture of float
  | Focal_point of Vec3.t
  | Blur_samples of int
  | Cam_transform of Transform.t

type global =
  | Assumed_gamma of float
  | Max_trace_level of int
  | Adc_bailout of float
  | Ambient_light of Color.t
  | Noise_generator of int  (** parsed; camlray has one noise *)
  | Number_of_waves of int  (** parsed; camlray's wave sources are fixed *)

type item =
  | Object of obj
  | Camera of Loc.t * camera_item list
  | Background of Color.rgbft
  | Global_settings of Loc.t * global list
  | Sky_sphere of Sky.t

type scene = { items : item list; version : float option; file : string }

(* Patterns carry their own transform; solid colours do not move. *)
let transform_texture t tex = Texture.transform t tex

let transform_obj t o =
  { o with xform = Transform.then_ o.xform t; texture = Option.map (transform_texture t) o.texture }
