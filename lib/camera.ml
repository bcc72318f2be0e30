type cylinder = { axis : int; angle : float; ur : Vec3.t; uu : Vec3.t; ud : Vec3.t; span : float }
type projection = Perspective | Orthographic | Cylinder of cylinder

let cylinder ~axis ~angle_deg ~right ~up ~direction =
  let span = if axis = 1 || axis = 3 then Vec3.length up else Vec3.length right in
  Cylinder
    {
      axis;
      angle = angle_deg *. Float.pi /. 180.;
      ur = Vec3.normalize right;
      uu = Vec3.normalize up;
      ud = Vec3.normalize direction;
      span;
    }

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

(* POV-Ray's cylinder cameras: along the axis the screen is flat (scaled
   by [span]); across it the ray turns by [angle] over the image width (or
   height). Types 3 and 4 slide the eye along the axis instead. *)
let cylinder_into k (loc : Vec3.t) sx sy (o : Vec3.m) (d : Vec3.m) =
  let about_up = k.axis = 1 || k.axis = 3 in
  let a = (if about_up then sx else sy) *. k.angle in
  let f = (if about_up then sy else sx) *. k.span in
  let s = Float.sin a and c = Float.cos a in
  let side = if about_up then k.ur else k.uu and axis = if about_up then k.uu else k.ur in
  let fd = if k.axis <= 2 then f else 0. in
  let fo = f -. fd in
  Vec3.set o (loc.x +. (fo *. axis.x)) (loc.y +. (fo *. axis.y)) (loc.z +. (fo *. axis.z));
  Vec3.set d
    ((s *. side.x) +. (fd *. axis.x) +. (c *. k.ud.x))
    ((s *. side.y) +. (fd *. axis.y) +. (c *. k.ud.y))
    ((s *. side.z) +. (fd *. axis.z) +. (c *. k.ud.z));
  Vec3.normalize_m d

let ray_into c sx sy o d =
  match c.projection with
  | Perspective ->
      Vec3.load o c.location;
      span_into c c.direction sx sy true d
  | Orthographic ->
      span_into c c.location sx sy false o;
      Vec3.load d c.direction;
      Vec3.normalize_m d
  | Cylinder k -> cylinder_into k c.location sx sy o d

let[@inline] origin c sx sy =
  match c.projection with
  | Perspective -> c.location
  | Orthographic -> span c c.location sx sy false
  | Cylinder k ->
      let o = Vec3.m () and d = Vec3.m () in
      cylinder_into k c.location sx sy o d;
      Vec3.of_m o

let[@inline] dir c sx sy =
  match c.projection with
  | Perspective -> span c c.direction sx sy true
  | Orthographic -> Vec3.normalize c.direction
  | Cylinder k ->
      let o = Vec3.m () and d = Vec3.m () in
      cylinder_into k c.location sx sy o d;
      Vec3.of_m d

let ray c sx sy = Ray.make (origin c sx sy) (dir c sx sy)

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
