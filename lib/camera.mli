(** Cameras, as POV-Ray places them: the final location, direction, right
    and up vectors (look_at and angle already applied by the scene
    compiler). Screen coordinates [sx], [sy] run from -0.5 to 0.5, [sy] up. *)

type projection =
  | Perspective
  | Orthographic
  | Cylinder of int
      (** POV-Ray's [cylinder 1] to [4]: 1 and 3 turn about up by [angle]
          across the width, 2 and 4 about right across the height; the
          other coordinate is flat (scaled by the length of up, resp.
          right); 3 and 4 move the eye along the axis instead of tilting
          the ray. *)
  | Fisheye  (** [angle] across the circle inscribed in the image *)
  | Omnimax  (** POV-Ray's 180-degree dome projection (no angle) *)
  | Ultra_wide_angle  (** [angle] across, [angle * |up| / |right|] down *)
  | Panoramic  (** 180 degrees across, tangent up and down *)
  | Spherical  (** [angle] across, [v_angle] down, as longitude and latitude *)
  | Mesh of Mesh_camera.t
      (** POV-Ray's [mesh_camera]: its rays come from
          {!Mesh_camera.ray_into}, several a pixel; {!ray_into} and the
          functions built on it give no ray for it ([false]). *)

type frame = {
  ur : Vec3.t;
  uu : Vec3.t;
  ud : Vec3.t;  (** right, up and direction, normalised *)
  lr : float;
  lu : float;  (** the lengths of right and up *)
  angle : float;  (** radians ([angle] of the scene; 90 degrees by default) *)
  v_angle : float;  (** radians; the spherical camera's vertical angle *)
}

type t = {
  projection : projection;
  location : Vec3.t;
  direction : Vec3.t;
  right : Vec3.t;
  up : Vec3.t;
  aperture : float;  (** 0: pinhole *)
  focal_distance : float;  (** along the view direction, for depth of field *)
  blur_samples : int;  (** 0: no focal blur (POV-Ray draws none without it) *)
  blur_samples_min : int;  (** lens rays always traced before the confidence test may stop *)
  blur_thresholds : float array;
      (** after [n] lens rays, the sampling of a pixel stops once the
          variance of the mean of each channel is under element [n - 1]
          (see {!blur_thresholds}) *)
  blur_points : float array;
      (** the lens points of focal blur in the unit disc, in the order
          used, as x0, y0, x1, y1, ... ({!blur_points}) *)
  frame : frame;  (** what the non-planar projections use *)
  normal : Normal.t option;
      (** POV-Ray's [normal { }] in a camera: each ray's direction turned
          as a surface normal would be, by the normal's pattern at the
          screen point (x0, y0, 0), x0 and y0 being [sx], [sy] for the
          planar projections and the angles the others make of them *)
}

val frame : right:Vec3.t -> up:Vec3.t -> direction:Vec3.t -> angle_deg:float -> v_angle_deg:float -> frame
(** The frame of the final vectors. *)

val blur_thresholds : samples:int -> confidence:float -> variance:float -> float array
(** POV-Ray's confidence test for focal blur: element [n - 1] is
    [variance * q(n) / q(samples - 1)], [q(d)] the chi-square quantile of
    [d] degrees of freedom with upper tail [confidence] (so the last
    threshold is about [variance]); all zero when [samples <= 1]. *)

val blur_points : int -> float array
(** [blur_points n]: [n] points of the unit disc (x0, y0, x1, y1, ...):
    the centre, six points of a hexagon of radius 0.95, then each the
    centre of the largest hole the points before it leave (the rim
    counting double), so that every prefix covers the disc evenly; random
    points past the 1024th. *)

val default : t
(** POV-Ray's default camera (location 0, direction z, right 1.33 x, up y). *)

val sees : t -> float -> float -> bool
(** Whether the camera sends a ray through the screen point: not outside
    the circle of a fisheye or an omnimax camera, nor below the omnimax's
    dome (POV-Ray leaves those pixels black). *)

val ray : t -> float -> float -> Ray.t
(** [ray cam sx sy]: the pinhole ray through the screen point. Directions
    are normalised. Where [sees] is false the ray is what the formula
    gives, which POV-Ray does not trace. *)

val origin : t -> float -> float -> Vec3.t
val dir : t -> float -> float -> Vec3.t
(** [origin] and [dir] of [ray], without the record. *)

val ray_into : t -> float -> float -> Vec3.m -> Vec3.m -> bool
(** [ray_into c sx sy o d]: {!origin} and {!dir} written into [o] and [d]
    (nothing allocated); the result is {!sees}. *)

val disc_into : t -> float -> float -> float -> float -> Vec3.m -> Vec3.m -> bool
(** [disc_into cam sx sy lx ly o d]: the ray through the screen point
    from the point [(lx, ly)] of the unit disc scaled onto the lens (x
    along right, y along up), into [o] and [d]; [false] where
    {!sees} is. *)

val lens_into : t -> float -> float -> float -> float -> Vec3.m -> Vec3.m -> bool
(** [lens_into cam sx sy u v o d]: {!ray_lens} written into [o] and [d]
    ({!ray_lens} goes through it). *)

val ray_lens : t -> float -> float -> float -> float -> Ray.t
(** [ray_lens cam sx sy u v]: as [ray], with the origin moved to the point
    [(u, v)] in [[0,1)^2] of the lens and aimed at the same point of the
    focal plane (the plane at [focal_distance] along the view axis). The
    lens is a disc of radius [aperture / 4], as in POV-Ray 3.7 (its focal
    blur moves the eye by [aperture / 2] times points of a disc of radius
    1/2). Same as [ray] when [aperture = 0]. *)

val pixel_coords : width:int -> height:int -> float -> float -> float * float
(** [pixel_coords ~width ~height px py] maps image coordinates (pixel
    centres at [i + 0.5], row 0 at the top) to [(sx, sy)]. *)

val pixel_x : width:int -> float -> float
(** [fst (pixel_coords ...)], without the pair. *)

val pixel_y : height:int -> float -> float
(** [snd (pixel_coords ...)], without the pair. *)
