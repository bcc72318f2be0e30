(** POV-Ray 3.7's [mesh_camera]: every camera ray starts on a face of a
    mesh and leaves along the face's normal. The faces are taken in
    source order (degenerate ones dropped, as POV-Ray's mesh parser does);
    how pixels pick faces is the distribution:

    - [Per_mesh] (0): ray [k] of a pixel comes from mesh [k], the face whose
      index is the pixel's number ([row * width + column]);
    - [Summed] (1): the meshes' faces in one list; ray [k] from face
      [pixel + k * total] (so only ray 0 is ever shot: POV-Ray's rule);
    - [Side_by_side] (2): one mesh per vertical strip of the image;
    - [Uv_map] (3): the first face of mesh 0 whose uv triangle holds the
      image point scaled to [0,1]^2 (texture baking).

    The image point is taken as POV-Ray 3.7.0 takes it (see {!ray_into}):
    row [j] of the image reads row [j - 1] of the faces.

    A ray leaves from the face's centroid (distributions 0 to 2) or from
    the point of the uv lookup (3), along the unit face normal
    [normalize ((P3 - P1) x (P2 - P1))] (with [smooth], distribution 3
    blends the corners' normals instead); it is moved [push] along that
    normal, reversed when [flip], then placed by the mesh's transform (the
    origin as a point, the direction as a normal) and normalised. A face
    number past the faces there are shoots no ray. *)

type distribution = Per_mesh | Summed | Side_by_side | Uv_map

type mesh
(** One mesh's faces as the camera reads them, flat. *)

val mesh :
  uv:bool -> verts:Float.Array.t -> faces:int array -> normals:Float.Array.t -> normal_faces:int array ->
  uvs:Float.Array.t -> uv_faces:int array -> mesh
(** The layout of {!Mesh.make} ([verts], [normals] 3 floats each, [faces],
    [normal_faces] 3 indices a triangle, [normal_faces] empty or [-1] for a
    flat triangle; [uvs] 2 floats each, [uv_faces] 3 indices a triangle or
    empty), indices in range. Faces whose corners are on one line are
    dropped. Vertices and face normals are rounded to single precision, as
    POV-Ray stores them; centroids are summed in single precision, as
    POV-Ray sums them. [uv]: also keep the corners, their uv and normals
    and a grid over uv space, for {!Uv_map}. *)

val faces : mesh -> int
(** Faces kept. *)

val dropped : mesh -> int
(** Faces dropped for having no area. *)

val has_uv : mesh -> bool
(** Some face has a uv triangle of non-zero area. *)

type t

val make :
  ?far:float -> rays:int -> distribution:distribution -> smooth:bool -> push:float -> flip:bool -> (mesh * Transform.t) array -> t
(** The camera: [rays] per pixel, the meshes in order with their
    transforms (to be invertible). Preconditions (the scene compiler
    checks them with located errors): at least one mesh; [rays >= 1];
    [rays <= ] the number of meshes for {!Per_mesh}; [rays = 1] for
    {!Side_by_side} and {!Uv_map}; [smooth] only with {!Uv_map}, whose
    mesh 0 was made with [~uv:true]. [push] is the camera location's z,
    [flip] whether its direction's z is below -1e-10. [far] (POV-Ray's
    optional third number): camera rays see nothing farther than this
    when positive (the default, 0, sets no limit). *)

val rays : t -> int
(** Rays per pixel. *)

val far : t -> float
(** How far camera rays see: [far] when positive, else infinity. *)

val ray_into : t -> width:int -> height:int -> int -> Vec3.m -> Vec3.m -> bool
(** [ray_into c ~width ~height k o d]: ray [k] ([0 .. rays - 1]) of the
    image point that comes in [o]'s x and y (camlray's image coordinates,
    pixel [(i, j)] spanning [[i, i+1) x [j, j+1)], row 0 at the top;
    floats passed to a call that is not inlined would be boxed). Writes
    the ray's origin into [o] and its unit direction into [d]; [false]
    when POV-Ray shoots no ray there ([o], [d] then hold anything).
    Allocates nothing.

    POV-Ray 3.7.0 reads the point [(px, py)] as [(x, y) = (px, py - 1)]
    clamped to [[0, width - 1] x [0, height - 1]] (measured: see the
    implementation); distributions 0 to 2 take column [int x] and row
    [int y], distribution 3 takes [(u, v) = ((x - 0.5) / width, 1 - (y +
    0.5) / height)]. *)
