(** Scene objects: a tree whose leaves are shapes placed by a full affine
    transform (its inverse stored once, in {!Transform.t}) with their
    texture and interior, and whose inner nodes are CSG operators.

    The scene compiler pushes transforms, textures and [no_shadow] down to
    the leaves (a CSG node's own fields are unused), turns [difference]
    into an intersection with inverted children and [inverse] of a CSG into
    its De Morgan dual, so inversion is only ever a leaf flag. A hit
    reports the leaf whose surface was crossed. *)

type t = private {
  geom : geom;
  xform : Transform.t;  (** object space to world space (leaves) *)
  texture : Texture.t;
  back : Texture.t;
      (** POV-Ray's [interior_texture]: what the inner side of the surface
          shows (seen from inside the solid); [texture] itself when none *)
  interior : Interior.t;
  no_shadow : bool;  (** casts no shadow (a node: none of its leaves does) *)
  inverted : bool;  (** leaf: inside and outside swapped, normal flipped *)
  clip : t array;  (** [clipped_by]: surfaces outside any of these are removed *)
  bound : t array;
      (** [bounded_by]: only rays that meet all of these (or start inside
          them) see the object, wherever they cross it *)
  bounds : (Vec3.t * Vec3.t) option;  (** world box; [None] when infinite *)
  index : index option;  (** a BVH over the children of a large union *)
  inv : Float.Array.t;  (** leaves: the inverse of [xform], 3x4 row-major, translation last *)
  uv : bool;  (** leaves: the texture is uv-mapped somewhere (the shader sets the hit's uv) *)
  lights : int;
      (** leaves: the lights that light the surface, an index into
          the scene's [light_sets]: 0 for the scene's global lights, another
          for the objects of a [light_group] *)
  photon : Photon.flags;  (** leaves: the words of its [photons] block (pushed down from CSG) *)
}

and geom =
  | Prim of Shape.t
  | Union of t array  (** every child surface; inside any child *)
  | Intersection of t array  (** surfaces inside all other children *)
  | Merge of t array  (** surfaces outside all other children; inside any *)

and index = {
  bvh : Bvh.t;
  bounded : t array;  (** children with finite bounds, in BVH leaf order *)
  unbounded : t array;
}

val make :
  ?xform:Transform.t -> ?texture:Texture.t -> ?back:Texture.t -> ?interior:Interior.t -> ?no_shadow:bool ->
  ?inverted:bool -> ?clip:t array -> ?lights:int -> ?photon:Photon.flags -> Shape.t -> t
(** A leaf ([lights]: its light set, 0 by default). A sphere under a similarity (rotations, uniform scales,
    translations) is stored moved, with the identity transform. *)

val union : ?clip:t array -> t array -> t
(** With 8 children or more, they get their own BVH. *)

val intersection : ?clip:t array -> ?frame:Transform.t -> t array -> t
(** Its box: the children's boxes intersected, axis-aligned planes
    bounding the half-space they keep; with [frame] (the transform from
    the space the intersection was written in to the world), also that
    box found in the frame, carried to the world. *)

val merge : ?clip:t array -> t array -> t

val with_clip : ?frame:Transform.t -> t -> t array -> t
(** Add [clipped_by] objects (world space). [frame]: the transform the
    clipped object was then moved by; its box is found in that frame too,
    as for {!intersection}. *)

val with_bound : t -> t array -> t
(** Add [bounded_by] objects (world space). The object's box is not
    narrowed: a ray that meets the bound crosses the object wherever it
    does. *)

val invert : t -> t
(** POV-Ray's [inverse]: flips a leaf; De Morgan on CSG nodes (a union or
    merge becomes an intersection of inverted children, an intersection a
    merge of inverted children). *)

type found = { mutable leaf : t; local : Ray.scratch; pt : Ray.scratch }
(** Where a query writes the leaf it hit, with its scratch space: the ray
    in a leaf's own space, a point for inside tests. One per domain and
    query kind: a query allocates nothing. *)

val found : t -> found

val hit : t -> Ray.t -> float -> Hit.t -> found -> bool
(** [hit o ray tmin h f]: nearest crossing of [o]'s surface in
    [(tmin, h.t)] (world space; distances in units of [ray.dir]). On
    success sets [h] and [f.leaf]. *)

val hit_s : t -> Ray.scratch -> float -> Hit.t -> found -> bool
(** {!hit} on a scratch ray (which must not be [f.local] or [f.pt]);
    allocates nothing: the crossings a CSG or a clip rejects are passed
    over by raising [h.floor], not by a new bound. *)

val intersect : t -> Ray.t -> float -> float -> float
(** Nearest distance in [(tmin, tmax)], or [infinity]. *)

val crossings : t -> Ray.t -> float -> float -> (t -> float -> bool) -> bool
(** [crossings o ray tmin tmax f] calls [f leaf t] on the crossings of
    [o]'s surface in [(tmin, tmax)], nearest first, until [f] returns
    [false] (then returns [false]). *)

val never : t -> bool
(** No object: the [opaque] of {!crossings_s} when nothing is known. *)

val crossings_s :
  t -> Ray.scratch -> float -> Hit.t -> found -> bool -> (t -> bool) -> (t -> Hit.t -> bool) -> bool
(** [crossings_s o ray tmin h f shadow opaque g]: {!crossings} within
    [(tmin, ray.far)] on a scratch ray, with [h] and [f] as scratch, [g
    leaf h] reading the crossing's distance in [h.t] (which it leaves as
    it is: a distance passed would be boxed); with
    [shadow], leaves marked [no_shadow] are skipped. [opaque leaf] says that
    [g leaf t] is [false] at every crossing of that leaf: [g] is then not
    called there (the walk stops), and a mesh so marked is asked for any one
    crossing, not walked nearest first (shadow rays only). *)

val normal : t -> Vec3.t -> Hit.t -> Vec3.t
(** [normal leaf p h]: outward unit world normal of a leaf at the world
    point [p], from the hit record that found it. *)

val normal_into : t -> Vec3.m -> Hit.t -> Vec3.m -> unit
(** [normal_into leaf p h n]: {!normal} with the point and the normal
    written in place ({!normal} goes through it): nothing allocated, for
    every shape, transformed or not. *)

val crossed_texture : t -> Vec3.m -> Hit.t -> Ray.scratch -> Vec3.m -> Texture.t
(** [crossed_texture leaf p h r n]: the texture a ray along [r]'s
    direction meets crossing the leaf's surface at [p]: its
    [interior_texture] where the ray leaves the solid (along the outward
    normal, which it leaves in [n] when there is an interior texture), its
    texture otherwise, as POV-Ray's shadow rays pick it. *)

val uv_into : t -> Vec3.m -> Hit.t -> Vec3.m -> unit
(** [uv_into leaf p h out]: the leaf's uv coordinates ({!Shape.uv_into}
    in its own frame) at the world point [p] found by [h], into [out]
    ([<u, v, 0>]), allocating nothing. *)

val solid_box : t -> (Vec3.t * Vec3.t) option
(** Where {!inside} can be true: [bounds] (the same value), except where a
    disc (whose inside is a half-space) makes it wider; [None] when
    unbounded. *)

val inside_s : t -> found -> bool
(** [inside] at the point held in [f.pt] (origin fields), [f] as scratch:
    nothing allocated. *)

val inside : t -> Vec3.t -> bool
(** POV-Ray's inside test at a world point. *)

val inside_pattern : t -> Pattern.inside
(** The object's inside test as the object pattern asks it (a point of
    pattern space taken as a world point): scratch per domain, nothing
    allocated per question. *)

val bounds : t -> (Vec3.t * Vec3.t) option
(** World-space axis-aligned bounds; [None] when infinite. *)

val next_tmin : Ray.t -> float -> float
(** [next_tmin ray t]: a distance just beyond [t], to look for the next
    crossing without finding the same one again. *)

val next_tmin_s : Ray.scratch -> float -> float
(** {!next_tmin} on a scratch ray. *)
