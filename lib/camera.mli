(** Cameras, as POV-Ray places them: the final location, direction, right
    and up vectors (look_at and angle already applied by the scene
    compiler). Screen coordinates [sx], [sy] run from -0.5 to 0.5, [sy] up. *)

type cylinder = {
  axis : int;
      (** POV-Ray's type: 1 and 3 turn about up (the horizontal angle is the
          [angle]), 2 and 4 about right; 3 and 4 move the eye along the axis
          instead of turning the ray. *)
  angle : float;  (** radians across the image in the turning direction *)
  ur : Vec3.t;
  uu : Vec3.t;
  ud : Vec3.t;  (** right, up and direction, normalised *)
  span : float;  (** the length of up (types 1, 3) or of right (2, 4) *)
}

type projection = Perspective | Orthographic | Cylinder of cylinder

type t = {
  projection : projection;
  location : Vec3.t;
  direction : Vec3.t;
  right : Vec3.t;
  up : Vec3.t;
  aperture : float;  (** 0: pinhole *)
  focal_distance : float;  (** along the view direction, for depth of field *)
  blur_samples : int;
}

val default : t
(** POV-Ray's default camera (location 0, direction z, right 1.33 x, up y). *)

val cylinder : axis:int -> angle_deg:float -> right:Vec3.t -> up:Vec3.t -> direction:Vec3.t -> projection
(** POV-Ray's [cylinder N] camera with the final vectors ([angle] in
    degrees, 90 when the scene gives none). *)

val ray : t -> float -> float -> Ray.t
(** [ray cam sx sy]: the pinhole ray through the screen point. Directions
    are normalised. *)

val origin : t -> float -> float -> Vec3.t
val dir : t -> float -> float -> Vec3.t
(** [origin] and [dir] of [ray], without the record. *)

val ray_into : t -> float -> float -> Vec3.m -> Vec3.m -> unit
(** [ray_into c sx sy o d]: {!origin} and {!dir} written into [o] and [d]
    (nothing allocated for a perspective camera). *)

val lens_into : t -> float -> float -> float -> float -> Vec3.m -> Vec3.m -> unit
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
