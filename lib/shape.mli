(** Shapes in object space, with POV-Ray 3.7's definitions (left-handed,
    see pov-facts §3). A query [hit s ray tmin h] finds the nearest crossing
    in the open interval [(tmin, h.t)] and records it in the scratch [h]
    (no allocation for the analytic shapes). *)

type t =
  | Sphere of { center : Vec3.t; radius : float }
  | Plane of { normal : Vec3.t; offset : float }
      (** unit [normal]; the surface is [normal . p = offset]; inside is
          [normal . p < offset] *)
  | Box of { lo : Vec3.t; hi : Vec3.t }
  | Cone of {
      base : Vec3.t;
      axis : Vec3.t;  (** unit, from base to top *)
      u : Vec3.t;  (** unit, perpendicular to [axis] *)
      v : Vec3.t;  (** [axis x u] *)
      length : float;
      r0 : float;  (** radius at the base *)
      r1 : float;  (** radius at the top *)
      open_ : bool;  (** no caps; inside is still the solid *)
    }  (** cylinders are cones with [r0 = r1] *)
  | Torus of { major : float; minor : float }  (** in the xz plane, axis y *)
  | Disc of { center : Vec3.t; normal : Vec3.t; radius : float; hole : float }
      (** unit [normal]; inside is the half-space behind it *)
  | Triangle of { a : Vec3.t; b : Vec3.t; c : Vec3.t; n : Vec3.t }  (** [n] unit *)
  | Smooth_triangle of { a : Vec3.t; b : Vec3.t; c : Vec3.t; na : Vec3.t; nb : Vec3.t; nc : Vec3.t }
  | Mesh of Mesh.t
  | Algebraic of Algebraic.t
      (** POV-Ray's [poly], [cubic], [quartic], [quadric]: unbounded *)
  | Text of Text.t  (** POV-Ray's [text] *)
  | Blob of Blob.t  (** POV-Ray's [blob] *)
  | Prism of Prism.t  (** POV-Ray's [prism] *)
  | Lathe of Lathe.t  (** POV-Ray's [lathe] *)
  | Sor of Sor.t  (** POV-Ray's [sor] *)
  | Superellipsoid of Superellipsoid.t  (** POV-Ray's [superellipsoid] *)
  | Julia of Julia.t  (** POV-Ray's [julia_fractal] (quaternion) *)
  | Polygon of Polygon.t  (** POV-Ray's [polygon] *)
  | Height_field of Height_field.t  (** POV-Ray's [height_field] *)
  | Isosurface of Isosurface.t  (** POV-Ray's [isosurface] *)

(** Constructors. They assume validated arguments (positive radii,
    distinct cone ends, non-degenerate triangles): the scene compiler
    reports bad input with its location before calling them. *)

val sphere : Vec3.t -> float -> t
val plane : Vec3.t -> float -> t
(** [plane n d]: POV-Ray's [plane { n, d }] ([n] is normalised). *)

val box : Vec3.t -> Vec3.t -> t
(** Any two opposite corners. *)

val cylinder : ?open_:bool -> Vec3.t -> Vec3.t -> float -> t
val cone : ?open_:bool -> Vec3.t -> float -> Vec3.t -> float -> t
(** [cone b rb t rt]. *)

val torus : float -> float -> t
val disc : ?hole:float -> Vec3.t -> Vec3.t -> float -> t
(** [disc c n r]: [n] is normalised. *)

val triangle : Vec3.t -> Vec3.t -> Vec3.t -> t
val smooth_triangle : Vec3.t -> Vec3.t -> Vec3.t -> Vec3.t -> Vec3.t -> Vec3.t -> t
(** [smooth_triangle p1 n1 p2 n2 p3 n3]: normals are normalised. *)

val hit : t -> Ray.t -> float -> Hit.t -> bool
(** [hit s ray tmin h]: nearest crossing in [(tmin, h.t)]; on success sets
    [h] (distance and which part was hit) and returns [true]. *)

val sphere_nearest : float -> float -> float -> float -> Ray.scratch -> float -> float -> float
(** [sphere_nearest cx cy cz radius ray lo hi]: the nearest crossing in
    (lo, hi) of the sphere, or infinity, with POV-Ray 3.7's arithmetic. *)

val hit_s : t -> Ray.scratch -> float -> Hit.t -> bool
(** {!hit} on a scratch ray: allocates nothing (a torus's solver aside). *)

val intersect : t -> Ray.t -> float -> float -> float
(** [intersect s ray tmin tmax]: the nearest distance in [(tmin, tmax)], or
    [infinity] (allocates a scratch; for tests and tools). *)

val normal : t -> Vec3.t -> Hit.t -> Vec3.t
(** Outward unit normal at a point on the surface, given the record of the
    hit that found it. *)

val uv_into : t -> Vec3.m -> Hit.t -> Vec3.m -> unit
(** [uv_into s p h out]: POV-Ray's uv coordinates, [<u, v, 0>], of the
    point [p] of the surface (shape space) found by the hit [h]: sphere
    (longitude, latitude), box (its faces unfolded into a cross; the face
    from [h.id]), torus (the angles around the axis and around the tube),
    mesh (the corners' uvs interpolated). Other shapes: [<0, 0, 0>], as
    POV-Ray gives shapes without uv coordinates. *)

val normal_into : t -> Vec3.m -> Hit.t -> Vec3.m -> unit
(** {!normal} written into a vector, nothing allocated ({!normal} goes
    through it); the point and the result may be the same vector. *)

val inside : t -> Vec3.t -> bool
(** POV-Ray's inside test (CSG and the [inside] function); triangles have
    no inside; meshes only with an [inside_vector]. *)

val inside_s : t -> Ray.scratch -> bool
(** {!inside} at the point held in the scratch's origin fields; allocates
    nothing (meshes aside). *)

val bounds : t -> (Vec3.t * Vec3.t) option
(** Axis-aligned bounds in object space; [None] for infinite shapes. *)
