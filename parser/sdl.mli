(** The evaluated scene description: what the parser and the directive
    evaluator produce, still located, in POV-Ray's own terms. The compile
    step ({!Compile}) turns it into the renderer's {!Camlray.Scene.t}. *)

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
  | Sor of { points : (float * float) array; sor_open : bool }  (** POV-Ray's [sor] *)
  | Superellipsoid of float * float  (** e, n *)
  | Julia of { jc : float array; hypercomplex : bool; cube : bool; max_iteration : int; precision : float }
      (** POV-Ray's [julia_fractal] (quaternion, default slice) *)
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
      (** POV-Ray's [light_group]: [global_lights], the children in source
          order (its light sources among them) *)

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

and blob_component = {
  comp : Blob.component;
  ctex : Texture.t option;
      (** its own texture, in the blob's space (moved by the component's
          transformations written after it); [None]: the blob's *)
}

and disc = { center : Vec3.t; normal : Vec3.t; radius : float; hole : float }

and mesh = {
  verts : Float.Array.t;  (** 3 floats per vertex *)
  normals : Float.Array.t;  (** 3 floats per normal *)
  faces : int array;  (** 3 vertex indices per triangle *)
  normal_faces : int array;  (** empty, or 3 normal indices per triangle (-1: flat) *)
  face_textures : int array;  (** empty, or an index into [textures] per triangle (-1: none) *)
  textures : Texture.t array;
  inside_vector : Vec3.t option;
  uvs : Float.Array.t;  (** 2 floats per uv_vectors entry (u, v) *)
  uv_faces : int array;  (** empty (no uvs), or 3 uv indices per triangle *)
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
  texture : Texture.t option;  (** [None]: inherit from a CSG parent *)
  inner : Texture.t option;  (** [interior_texture] ([None]: inherit, or the texture) *)
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
  | Mesh_camera of mesh_camera  (** POV-Ray's [mesh_camera { }] *)

and mesh_camera = {
  mc_loc : Loc.t;  (** the [mesh_camera] word *)
  rays : Loc.t * float;  (** rays per pixel, as written *)
  distribution : Loc.t * float;  (** the distribution type, as written *)
  max_distance : float option;  (** the optional third number: how far camera rays see *)
  meshes : obj list;  (** the mesh objects in order, with their transforms *)
  smooth : Loc.t option;  (** [smooth], where written *)
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

type scene = {
  items : item list;  (** in source order *)
  version : float option;  (** the [#version] in force at the start *)
  file : string;
}

val transform_obj : Transform.t -> obj -> obj
(** Apply a transform to an object and to the texture already attached to
    it (POV-Ray's rule: a texture written before a transform moves with
    the object). *)

val no_image : int
(** The object is not seen by camera rays (nor through refraction from
    them); it still casts shadows and shows in reflections. *)

val no_reflection : int
(** The object is not seen by rays after a reflection. *)

val double_illuminate : int
val uv_mapping : int
val no_radiosity : int
(** [no_radiosity]: hidden from radiosity's gather rays. *)
(** [uv_mapping] in an object: the textures and pigments written after it are uv-mapped. *)
(** Lights behind the surface light it too. *)
