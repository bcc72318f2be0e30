(** Triangle meshes with their own BVH over triangles (the storage behind
    POV-Ray's [mesh] and [mesh2]). Corners are copied per triangle in BVH
    leaf order, so the triangles a leaf holds sit together in memory.
    Memory per triangle: 72 bytes of corners, 8 of BVH permutation and
    about 16 of BVH nodes (~96; 24 more with per-vertex normals, plus 24
    per normal); see {!bytes}. *)

type t

val make :
  ?uv:Float.Array.t * int array ->
  par:(int -> (int -> unit) -> unit) option -> verts:Float.Array.t -> normals:Float.Array.t -> faces:int array -> normal_faces:int array ->
  inside_vector:Vec3.t option -> unit -> t
(** [verts] and [normals] hold 3 floats per vertex / normal; [faces] 3
    vertex indices per triangle; [normal_faces] is either empty (flat
    triangles) or 3 normal indices per triangle (smooth triangles; an index
    [< 0] makes that triangle flat). Indices must be in range (the caller
    checks them); normals are normalised here. Degenerate triangles (zero area) are dropped; see
    {!triangles}. [inside_vector] enables the inside test (POV-Ray's rule:
    odd crossings along it). [uv]: the surface coordinates (2 floats
    each) and 3 indices into them per triangle (in range: the caller
    checks them), for {!uv_into}. [par]: build the BVH in parallel with it
    (see {!Bvh.build}; the same tree). *)

val triangles : t -> int
(** Number of triangles kept. *)

val bytes : t -> int
(** Memory held (arrays and BVH). *)

val bounds : t -> Vec3.t * Vec3.t
(** A point box at the origin for an empty mesh. *)

val hit : t -> Ray.t -> float -> Hit.t -> bool
(** Nearest triangle in [(tmin, h.t)]: sets [h.t], the barycentric [h.u],
    [h.v] and the triangle index [h.id]. *)

val hit_s : t -> Ray.scratch -> float -> Hit.t -> bool
(** {!hit} on a scratch ray, allocation-free. *)

val any_s : t -> Ray.scratch -> float -> Hit.t -> bool
(** [any_s m ray tmin h]: some triangle crossed in [(tmin, h.t)], the
    first one the BVH walk meets, not the nearest (a shadow ray through an
    opaque mesh); on success sets [h] as {!hit_s} does. *)

val normal : t -> Hit.t -> Vec3.t
(** Unit normal of the triangle recorded in the hit (interpolated for
    smooth triangles). *)

val normal_into : t -> Hit.t -> Vec3.m -> unit
(** {!normal} written into a vector the caller owns. *)

val uv_into : t -> Hit.t -> Vec3.m -> unit
(** [uv_into m h out]: POV-Ray's uv coordinates of the hit, [<u, v, 0>]:
    the triangle's corners' interpolated by the hit's barycentric
    weights; [<0, 0, 0>] for a mesh made without [uv] (as POV-Ray). *)

val inside : t -> Vec3.t -> bool

val inside_xyz : t -> float -> float -> float -> bool
(** {!inside} of a point given by its coordinates (nothing allocated
    without an inside vector). *)

val tri_hit :
  float -> float -> float -> float -> float -> float -> float -> float -> float ->
  Ray.scratch -> float -> Hit.t -> bool
(** [tri_hit ax ay az bx by bz cx cy cz ray tmin h]: Moller-Trumbore for one
    triangle; on a hit in [(tmin, h.t)] sets [h.t], [h.u] (weight of b),
    [h.v] (weight of c). *)

val smooth_normal : Vec3.t -> Vec3.t -> Vec3.t -> float -> float -> Vec3.t
(** Barycentric interpolation of three vertex normals, normalised. *)

val smooth_normal_into : Vec3.t -> Vec3.t -> Vec3.t -> Hit.t -> Vec3.m -> unit
(** [smooth_normal n1 n2 n3 h.u h.v] written into a vector. *)
