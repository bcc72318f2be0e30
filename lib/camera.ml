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

let[@inline] pixel_x ~width px = (px /. float_of_int width) -. 0.5
let[@inline] pixel_y ~height py = 0.5 -. (py /. float_of_int height)
let pixel_coords ~width ~height px py = (pixel_x ~width px, pixel_y ~height py)

(* [a + sx right + sy up], normalized when [unit], into [out] *)
let[@inline] span_into c (a : Vec3.t) sx sy unit (out : Vec3.m) =
  let x = a.x +. (sx *. c.right.x) and y = a.y +. (sx *. c.right.y) and z = a.z +. (sx *. c.right.z) in
  let x = x +. (sy *. c.up.x) and y = y +. (sy *. c.up.y) and z = z +. (sy *. c.up.z) in
  let l = if unit then Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) else 0. in
  if l > 0. then
    let k = 1. /. l in
    Vec3.set out (k *. x) (k *. y) (k *. z)
  else Vec3.set out x y z

(* the same as a new vector (the path tracer's camera rays): written
   again rather than through [span_into], which would allocate a second
   vector per sample *)
let[@inline] span c (a : Vec3.t) sx sy unit =
  let x = a.x +. (sx *. c.right.x) and y = a.y +. (sx *. c.right.y) and z = a.z +. (sx *. c.right.z) in
  let x = x +. (sy *. c.up.x) and y = y +. (sy *. c.up.y) and z = z +. (sy *. c.up.z) in
  let l = if unit then Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) else 0. in
  if l > 0. then
    let k = 1. /. l in
    Vec3.make (k *. x) (k *. y) (k *. z)
  else Vec3.make x y z

let[@inline] origin c sx sy =
  match c.projection with Perspective -> c.location | Orthographic -> span c c.location sx sy false

let[@inline] dir c sx sy =
  match c.projection with
  | Perspective -> span c c.direction sx sy true
  | Orthographic -> Vec3.normalize c.direction

let ray c sx sy = Ray.make (origin c sx sy) (dir c sx sy)

let ray_into c sx sy o d =
  match c.projection with
  | Perspective ->
      Vec3.load o c.location;
      span_into c c.direction sx sy true d
  | Orthographic ->
      span_into c c.location sx sy false o;
      Vec3.load d c.direction;
      Vec3.normalize_m d

let lens_into c sx sy u v (o : Vec3.m) (d : Vec3.m) =
  ray_into c sx sy o d;
  if c.aperture > 0. then begin
    (* POV-Ray's lens has radius aperture/4 (checked by rendering a point
       light out of focus); uniform polar mapping of the square onto it *)
    let rad = 0.25 *. c.aperture *. Float.sqrt u in
    let phi = 2. *. Float.pi *. v in
    let kc = rad *. Float.cos phi and ks = rad *. Float.sin phi in
    let rt = c.right and up = c.up and dir = c.direction in
    let ox = (kc *. Vec3.unit_k rt.x rt.y rt.z 0) +. (ks *. Vec3.unit_k up.x up.y up.z 0)
    and oy = (kc *. Vec3.unit_k rt.x rt.y rt.z 1) +. (ks *. Vec3.unit_k up.x up.y up.z 1)
    and oz = (kc *. Vec3.unit_k rt.x rt.y rt.z 2) +. (ks *. Vec3.unit_k up.x up.y up.z 2) in
    let ax = Vec3.unit_k dir.x dir.y dir.z 0 and ay = Vec3.unit_k dir.x dir.y dir.z 1
    and az = Vec3.unit_k dir.x dir.y dir.z 2 in
    let tf = c.focal_distance /. ((d.mx *. ax) +. (d.my *. ay) +. (d.mz *. az)) in
    let fx = o.mx +. (tf *. d.mx) and fy = o.my +. (tf *. d.my) and fz = o.mz +. (tf *. d.mz) in
    Vec3.set o (o.mx +. ox) (o.my +. oy) (o.mz +. oz);
    Vec3.set d (fx -. o.mx) (fy -. o.my) (fz -. o.mz);
    Vec3.normalize_m d
  end

let ray_lens c sx sy u v =
  let o = Vec3.m () and d = Vec3.m () in
  lens_into c sx sy u v o d;
  Ray.make (Vec3.of_m o) (Vec3.of_m d)
