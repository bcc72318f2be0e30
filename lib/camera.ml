type projection = Perspective | Orthographic

type t = {
  projection : projection;
  location : Vec3.t;
  direction : Vec3.t;
  right : Vec3.t;
  up : Vec3.t;
  aperture : float;
  focal_distance : float;
  blur_samples : int;
}

let default =
  {
    projection = Perspective;
    location = Vec3.zero;
    direction = Vec3.unit_z;
    right = Vec3.make 1.33 0. 0.;
    up = Vec3.unit_y;
    aperture = 0.;
    focal_distance = 1.;
    blur_samples = 0;
  }

let pixel_coords ~width ~height px py =
  ((px /. float_of_int width) -. 0.5, 0.5 -. (py /. float_of_int height))

let ray c sx sy =
  match c.projection with
  | Perspective ->
      let d = Vec3.madd (Vec3.madd c.direction sx c.right) sy c.up in
      Ray.make c.location (Vec3.normalize d)
  | Orthographic ->
      let o = Vec3.madd (Vec3.madd c.location sx c.right) sy c.up in
      Ray.make o (Vec3.normalize c.direction)

(* POV-Ray (tracepixel.cpp, JitterCameraRay): the eye moves by
   (aperture / 2) x a point of the disc of radius 1/2, so the lens radius is
   aperture / 4; the unnormalised ray direction (direction + sx right +
   sy up) scaled by focal_distance / |direction| stays aimed at the same
   point, so the in-focus surface is the plane at focal_distance along the
   view axis. *)
let ray_lens c sx sy u v =
  let r = ray c sx sy in
  if c.aperture <= 0. then r
  else
    let rad = 0.25 *. c.aperture *. Float.sqrt u in
    let phi = 2. *. Float.pi *. v in
    let ru = Vec3.normalize c.right and rv = Vec3.normalize c.up in
    let offset = Vec3.add (Vec3.scale (rad *. Float.cos phi) ru) (Vec3.scale (rad *. Float.sin phi) rv) in
    let axis = Vec3.normalize c.direction in
    let tf = c.focal_distance /. Vec3.dot r.dir axis in
    let focus = Ray.at r tf in
    let o = Vec3.add r.origin offset in
    Ray.make o (Vec3.normalize (Vec3.sub focus o))
