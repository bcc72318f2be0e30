open Camlray

type shape =
  | Sphere of Vec3.t * float
  | Plane of Vec3.t * float
  | Unit_plane of Vec3.t * float
      (** a plane moved, turned or scaled as POV-Ray changes its own
          numbers: its normal already made a unit vector POV-Ray's way
          (and turned since), its offset along it *)
  | Box of Vec3.t * Vec3.t
  | Cone of cone  (** cylinders too *)
  | Torus of float * float
  | Disc of disc
  | Triangle of Vec3.t * Vec3.t * Vec3.t
  | Smooth_triangle of Vec3.t * Vec3.t * Vec3.t * Vec3.t * Vec3.t * Vec3.t
      (** points and normals: p1, p2, p3, n1, n2, n3 *)
  | Mesh of mesh
  | Algebraic of algebraic
      (** [poly], [cubic], [quartic], [quadric] *)
  | Text of text
  | Blob of float * blob_component list  (** threshold, components *)
  | Prism of prism
  | Lathe of Prism.spline * (float * float) array
  | Sor of { points : (float * float) array; sor_open : bool }
  | Superellipsoid of float * float  (** e, n *)
  | Julia of { jc : float array; hypercomplex : bool; cube : bool; max_iteration : int; precision : float }
  | Polygon of Vec3.t array  (** the points as written *)
  | Height_field of height_field
  | Isosurface of isosurface
  | Csg of csg * obj list
      (** children in source order, transforms and texture of their own *)
  | Inverse of obj
      (** [inverse] wraps the object it modifies: modifiers after it apply to
          the wrapper (a one-child CSG node) *)
  | Clipped of obj * obj list
      (** [clipped_by]: the object and the clipping objects; later
          transforms move both *)
  | Bounded of obj * obj list
      (** [bounded_by]: the object and its bounding objects (the same way) *)
  | Light of light
  | Light_group of bool * obj list

and csg = Union | Intersection | Difference | Merge

and cone = { base : Vec3.t; base_r : float; top : Vec3.t; top_r : float; open_ : bool; cylinder : bool }

and algebraic = {
  order : int;
  coef : float array;  (** POV-Ray's term order (see {!Camlray.Algebraic.make}) *)
  quadric : bool;  (** a [quadric]: inside where the polynomial is <= 0 *)
}

and height_field = {
  source : hf_source;
  smooth : bool;
  water : float;  (** water_level, 0 .. 1 *)
  field : Height_field.t;  (** the grid read or computed *)
}

and hf_source =
  | Hf_file of string option * string  (** the file type word (png, pgm, ...) if written, the file as written *)
  | Hf_function of int * int * string option
      (** width, height, the body's text (None for a pigment function) *)

and text = {
  font : string;  (** as written *)
  chars : string;
  thickness : float;
  offset : Vec3.t;
  glyphs : Text.t;  (** set with the font found *)
}

and prism = {
  spline : Prism.spline;
  sweep : Prism.sweep;
  height1 : float;
  height2 : float;
  points : (float * float) array;
  no_caps : bool;  (** [open] *)
}

and isosurface = {
  fn : Fn.t;  (** a float function of 3 parameters, supported *)
  container : Isosurface.container;  (** [contained_by], box [{-1, 1}] unless given *)
  threshold : float;
  accuracy : float;
  max_gradient : float;
  evaluate : (float * float * float) option;  (** read, not used (see docs/language.md) *)
  iso_open : bool;
  max_trace : int;  (** [max_int] for [all_intersections] *)
}

and blob_component = { comp : Blob.component; ctex : Texture.t option }

and disc = { center : Vec3.t; normal : Vec3.t; radius : float; hole : float }

and mesh = {
  verts : Float.Array.t;  (** 3 floats per vertex *)
  normals : Float.Array.t;  (** 3 floats per normal *)
  faces : int array;  (** 3 vertex indices per triangle *)
  normal_faces : int array;  (** empty, or 3 normal indices per triangle (-1: flat) *)
  face_textures : int array;  (** empty, or an index into [textures] per triangle (-1: none) *)
  textures : Texture.t array;
  inside_vector : Vec3.t option;
  uvs : Float.Array.t;
  uv_faces : int array;
}

and light = {
  position : Vec3.t;
  color : Color.t;
  kind : light_kind;
  point_at : Vec3.t;  (** <0, 0, 1> unless given *)
  parallel : bool;  (** POV-Ray's parallel flag (a cylinder sets it) *)
  fade_distance : float;
  fade_power : float;
  shadowless : bool;
      (** POV-Ray's fill light: [shadowless] makes the light a point
          light again (a later [spotlight] or [cylinder] casts shadows) *)
  media_interaction : bool;
  media_attenuation : bool;
  area : Light.area option;
  looks_like : obj option;  (** drawn at the light's position, casts no shadow *)
  projected_through : obj option;
      (** the light reaches only what sees it through this object; written
          in the light's frame as it stood when read (transformations
          written after [projected_through] move it) *)
}

(** POV-Ray's light types as a light_source reads them; the compiled
    {!Light.kind} follows from the type and the parallel flag. *)
and light_kind =
  | Point_light
  | Spot_light of { radius : float; falloff : float; tightness : float }  (** degrees *)
  | Cylinder_light of { radius : float; falloff : float; tightness : float }
      (** distances from the axis *)

and obj = {
  loc : Loc.t;
  shape : shape;
  xform : Transform.t;
  texture : Texture.t option;
  inner : Texture.t option;
  interior : Interior.t option;
  no_shadow : bool;
  hollow : bool;
  flags : int;  (** {!no_image}, {!no_reflection}, {!double_illuminate} *)
  photon : Photon.flags;  (** its [photons { }] block; a light's too *)
}

type camera_item =
  | Perspective
  | Orthographic
  | Cylinder_camera of int  (** POV-Ray's [cylinder 1] to [cylinder 4] *)
  | Fisheye
  | Omnimax
  | Ultra_wide_angle
  | Panoramic
  | Spherical_camera
  | Location of Vec3.t
  | Look_at of Vec3.t
  | Angle of float
  | Angles of float * float  (** the spherical camera's [angle h, v] *)
  | Right of Vec3.t
  | Up of Vec3.t
  | Direction of Vec3.t
  | Sky of Vec3.t
  | Aperture of float
  | Focal_point of Vec3.t
  | Blur_samples of int * int  (** [blur_samples [MIN,] MAX]: the minimum (0 when absent), the maximum *)
  | Confidence of float  (** focal blur's confidence test (0.9) *)
  | Variance of float  (** and its variance (1/128) *)
  | Cam_transform of Transform.t
  | Cam_normal of Normal.t  (** [normal { }]: perturbs the rays' directions *)
  | Mesh_camera of mesh_camera

and mesh_camera = {
  mc_loc : Loc.t;
  rays : Loc.t * float;
  distribution : Loc.t * float;
  max_distance : float option;
  meshes : obj list;
  smooth : Loc.t option;
}

type global =
  | Assumed_gamma of float
  | Max_trace_level of int
  | Irid_wavelength of Color.t
  | Adc_bailout of float
  | Ambient_light of Color.t
  | Radiosity of Radiosity.t  (** [radiosity { ... }]; [keep_ambient] is set by the compiler *)
  | Noise_generator of int  (** the scene's, for patterns naming none *)
  | Number_of_waves of int  (** the number of wave sources of ripples and waves (at least 1) *)
  | Photons of Photon.settings  (** [photons { ... }]: caustics in whitted mode *)

type item =
  | Object of obj
  | Camera of Loc.t * camera_item list
  | Background of Color.rgbft
  | Global_settings of Loc.t * global list
  | Sky_sphere of Sky.t
  | Fog of Fog.t
  | Rainbow of Rainbow.t
  | Media of Media.t  (** scene-level (atmospheric) media *)

type scene = { items : item list; version : float option; file : string }

(* Patterns carry their own transform; solid colours do not move. *)
let transform_texture t tex = Texture.transform t tex

(* POV-Ray 3.7 moves and scales a box's corners (boxes.cpp) until it is
   first rotated or given a matrix or a transform { }; only from then on
   does the box keep a transformation. Its faces then lie where POV-Ray's do to the last bit
   (a face on a pattern's cell boundary shows the same cell). *)
let baked_box t o =
  match o.shape with
  | Box (a, b) when Transform.is_identity o.xform -> (
      match Transform.as_translation t with
      | Some v -> Some (Box (Vec3.add a v, Vec3.add b v))
      | None -> (
          match Transform.as_scale t with
          | Some s ->
              let a = Vec3.make (a.x *. s.x) (a.y *. s.y) (a.z *. s.z)
              and b = Vec3.make (b.x *. s.x) (b.y *. s.y) (b.z *. s.z) in
              Some (Box (Vec3.min a b, Vec3.max a b))
          | None -> None))
  | _ -> None

(* POV-Ray 3.7's plane (planes.cpp) keeps its own numbers until it is
   given a matrix or a transform { }: its normal is made a unit vector
   (times 1/length) when it is read; translate moves its offset by the
   sum of the normal's and the vector's products, rotate turns the
   normal (not made a unit vector again), scale divides the normal by
   the factors, makes it a unit vector again and divides the offset by
   its length. *)
let baked_plane t o =
  let step (n : Vec3.t) d =
    match Transform.as_translation t with
    | Some v -> Some (Unit_plane (n, d +. ((n.x *. v.x) +. (n.y *. v.y) +. (n.z *. v.z))))
    | None -> (
        match Transform.as_scale t with
        | Some s ->
            let m = Vec3.make (n.x /. s.x) (n.y /. s.y) (n.z /. s.z) in
            let l = Vec3.length m in
            Some (Unit_plane (Vec3.normalize m, d /. l))
        | None -> if Transform.is_turn t then Some (Unit_plane (Transform.vector t n, d)) else None)
  in
  if not (Transform.is_identity o.xform) then None
  else
    match o.shape with
    | Plane (n, d) when Vec3.length n > 0. -> step (Vec3.normalize n) d
    | Unit_plane (n, d) -> step n d
    | _ -> None

let transform_obj t o =
  let o =
    match baked_box t o with
    | Some shape -> { o with shape }
    | None -> (
        match baked_plane t o with
        | Some shape -> { o with shape }
        | None -> { o with xform = Transform.then_ o.xform t })
  in
  { o with texture = Option.map (transform_texture t) o.texture;
    inner = Option.map (transform_texture t) o.inner;
    interior = Option.map (Interior.transform t) o.interior }

let no_image = 1
let no_reflection = 2
let double_illuminate = 4
let uv_mapping = 8
let no_radiosity = 16
