(** Helpers for the semantic actions of grammar_objects.mly: building
    located {!Sdl.obj} values for shapes, CSG, meshes, and the object
    modifiers that change the shape ([open], [inverse], [clipped_by]). *)

val obj : Loc.t -> Sdl.shape -> (Sdl.obj -> Sdl.obj) list -> Sdl.obj
(** A fresh object (identity transform, no texture) with the modifiers
    applied in order; a plain texture is shared ({!share_texture}). *)

val share_texture : Camlray.Texture.t -> Camlray.Texture.t
(** One record for equal plain textures (one layer, a plain colour, no
    normal): the first one seen since {!forget_textures}. *)

val forget_textures : unit -> unit
(** Start sharing afresh (a new parse; the end of a compile). *)

val set_open : Loc.t -> Sdl.obj -> Sdl.obj
(** [open] on a cylinder or cone (a warning on anything else). *)

val inverse : Sdl.obj -> Sdl.obj
(** Wrap in an {!Sdl.Inverse} node that takes over the texture and
    interior, so that later modifiers apply to it. *)

val clipped : Sdl.obj list -> Sdl.obj -> Sdl.obj
(** Wrap in an {!Sdl.Clipped} node (the same way as {!inverse}). *)

val bounded : Sdl.obj list -> Sdl.obj -> Sdl.obj
(** Wrap in an {!Sdl.Bounded} node (the same way as {!inverse}). *)

val bound_by_clip : Loc.t -> Sdl.obj -> Sdl.obj
(** [bounded_by { clipped_by }]: the clipping objects as bounds too. *)

val clip_by_bound : Loc.t -> Sdl.obj -> Sdl.obj
(** [clipped_by { bounded_by }]: the bounding objects as clips too. *)

val algebraic : Loc.t -> string -> int -> Value.t -> Sdl.shape
(** [algebraic loc what order coefficients]: a [cubic] (3) or [quartic] (4),
    the coefficients a vector of their number ([what] names the shape in
    the error otherwise). *)

val poly : Loc.t -> Loc.t -> Value.t -> Value.t -> Sdl.shape
(** [poly order_loc loc order coefficients]: orders 2 to
    {!Camlray.Algebraic.max_order}. *)

val text : Loc.t -> string -> string -> float -> Camlray.Vec3.t -> Sdl.shape
(** [text loc font chars thickness offset]: [text { ttf font chars
    thickness, offset }], the font found as an include file ([loc] names
    it in errors). *)

val prism : Loc.t -> string list -> float -> float -> Loc.t * int -> (Loc.t * Value.t) list -> Sdl.shape
(** [prism loc kinds h1 h2 (nloc, n) points]: its spline and sweep
    keywords, heights, announced count and points (checked with located
    errors). *)

val lathe : Loc.t -> string list -> Loc.t * int -> (Loc.t * Value.t) list -> Sdl.shape
(** [lathe loc kinds (nloc, n) points] (checked with located errors). *)

(** An isosurface's parameters and modifiers, in the order written. *)
type iso_item =
  | Iso_container of Camlray.Isosurface.container
  | Iso_threshold of float
  | Iso_accuracy of Loc.t * float
  | Iso_max_gradient of Loc.t * float
  | Iso_evaluate of Loc.t * (float * float * float)
  | Iso_max_trace of Loc.t * int
  | Iso_mod of (Sdl.obj -> Sdl.obj)

val iso_sphere : Loc.t -> Camlray.Vec3.t -> float -> Camlray.Isosurface.container
(** A [contained_by { sphere { c, r } }]: a negative radius taken as its
    size, as POV-Ray takes it. *)

val isosurface : Loc.t -> Loc.t -> Fn.t -> iso_item list -> Sdl.obj
(** [isosurface loc floc f items]: POV-Ray's defaults for what is not
    given; located errors for an unsupported function or one that does
    not take 3 parameters ([floc]), a non-positive accuracy or
    max_gradient, a max_trace below 1. *)

val polygon : Loc.t -> Loc.t * int -> (Loc.t * Value.t) list -> Sdl.shape
(** [polygon { n, p1, ... pn }]: the count checked, the points in one
    plane (2-vectors have z 0); an outline left open is closed with a
    warning. *)

type hf_source = Hf_file of Loc.t * string option * string | Hf_fn of Loc.t * int * int * Fn.t * string option
type hf_option = Hf_smooth | Hf_water of Loc.t * float

val height_field : hf_source -> hf_option list -> Sdl.shape
(** [height_field { png "file" | function W, H { ... } [smooth] [water_level w] }]:
    the file found as fonts are (a located error when it is missing or
    unreadable), the function sampled at W x H points; see
    {!Camlray.Height_field}. *)

val julia :
  Loc.t ->
  Value.t ->
  [< `Cube | `Iter of Loc.t * Value.t | `Prec of Loc.t * Value.t | `Quat | `Hyper of Loc.t | `Slice of Loc.t * Value.t * Value.t | `Sqr ] list ->
  Sdl.shape
(** POV-Ray's [julia_fractal { <a, b, c, d> ... }] (quaternion sqr or cube;
    defaults max_iteration 20, precision 20; only the default slice). *)

val internal_font : Loc.t -> int -> string
(** the file of POV-Ray's built-in font N (0 to 3) *)

val superellipsoid : Loc.t -> Value.t -> Sdl.shape
(** [superellipsoid { <e, n> }]: both exponents positive. *)

val blob_sphere : Loc.t -> Camlray.Vec3.t -> float -> float -> Camlray.Blob.component
(** A blob's [sphere { centre, radius, [strength] s }] (or [component s,
    r, centre]); a radius that is not positive is an error. *)

val blob_cylinder : Loc.t -> Camlray.Vec3.t -> Camlray.Vec3.t -> float -> float -> Camlray.Blob.component

val quadric : Camlray.Vec3.t -> Camlray.Vec3.t -> Camlray.Vec3.t -> float -> Sdl.shape
(** [quadric <A,B,C> <D,E,F> <G,H,I> J]: A x^2 + B y^2 + C z^2 + D xy +
    E xz + F yz + G x + H y + I z + J. *)

type mesh_tri
(** A triangle of a [mesh] block. *)

val mesh_triangle :
  Loc.t -> Camlray.Vec3.t array -> (Loc.t * Value.t) list option -> Camlray.Texture.t option -> mesh_tri
(** corners (3, or 6 with normals), the corners' uv_vectors, a texture *)
(** 3 points (flat) or 6 vectors p1 n1 p2 n2 p3 n3 (smooth). *)

val mesh : Loc.t -> mesh_tri list -> Sdl.shape
(** A [mesh] of individual triangles (vertices stored flat). *)

type mesh2_block
(** One block of a [mesh2]. *)

type items
(** The items of a [mesh2] block, kept flat as they are read (values and
    where they stand): checked when the block ends. *)

val items : unit -> items

val add_item : items -> Lexing.position -> Lexing.position -> Value.t -> items
(** The items with one more: written into the shared store at the next
    index (an action the parser runs ahead writes the same item there
    again). *)

val vertex_vectors : Loc.t -> Value.t -> items -> mesh2_block
val normal_vectors : Loc.t -> Value.t -> items -> mesh2_block
val face_indices : Loc.t -> Value.t -> items -> mesh2_block
val normal_indices : Loc.t -> Value.t -> items -> mesh2_block
val texture_list : Loc.t -> Value.t -> Camlray.Texture.t list -> mesh2_block
val ignored_block : mesh2_block

val uv_vectors : Loc.t -> Value.t -> items -> mesh2_block
(** [uv_vectors { n, <u, v>, ... }]: the surface coordinates uv_mapping reads. *)

val uv_indices : Loc.t -> Value.t -> items -> mesh2_block
(** [uv_indices { n, <a, b, c>, ... }]: one per face (else the face indices pick the uvs). *)
(** [uv_vectors], [uv_indices]: read and ignored. *)

val mesh2 : Loc.t -> mesh2_block list -> Sdl.shape
(** Check counts and indices (located errors) and build the mesh. *)

val inside_vector : Loc.t -> Camlray.Vec3.t -> Sdl.obj -> Sdl.obj
(** [inside_vector] on a mesh (a warning on anything else). *)

val csg : Loc.t -> Sdl.csg -> [ `Child of Sdl.obj | `Mod of Sdl.obj -> Sdl.obj ] list -> Sdl.obj
(** A CSG object from its children and modifiers (modifiers apply to the
    whole, in order). *)

val default_texture : Sdl.obj -> Sdl.obj
(** An object placed in the scene without a texture gets the [#default]
    texture in force there (its CSG children without one inherit it).
    Known difference: "there" is after the parser's lookahead, so an
    object followed directly by a [#default] gets that new default. *)

val blob_component : Loc.t -> (Sdl.obj -> Sdl.obj) list -> Camlray.Blob.component -> Sdl.blob_component
(** A blob's sphere or cylinder with its modifiers (transformations and
    texture, as an object takes them, in order): moves, turns and even
    scales move it; any other transformation places it
    ({!Camlray.Blob.place}). *)

val bicubic_patch : Loc.t -> u_steps:int -> v_steps:int -> Camlray.Vec3.t array -> Sdl.shape
(** POV-Ray's [bicubic_patch] of 16 control points, as a smooth mesh of
    2^u_steps x 2^v_steps cells (two triangles each) with the patch's
    normals at their corners. *)

val sor : Loc.t -> Loc.t * int -> (Loc.t * Value.t) list -> open_:bool -> Sdl.shape
(** POV-Ray's [sor { n, <r, y> ... [open] }]: the count checked, the
    points 2-vectors with rising heights. *)

val light_group :
  Loc.t -> Sdl.obj list -> [ `Xf of Camlray.Transform.t | `Global of bool ] list -> Sdl.obj
(** [light_group { children mods }]: the transformations in order, the
    last [global_lights] (off unless given). *)
