type projection =
  | Perspective
  | Orthographic
  | Cylinder of int
  | Fisheye
  | Omnimax
  | Ultra_wide_angle
  | Panoramic
  | Spherical
  | Mesh of Mesh_camera.t

type frame = { ur : Vec3.t; uu : Vec3.t; ud : Vec3.t; lr : float; lu : float; angle : float; v_angle : float }

type t = {
  projection : projection;
  location : Vec3.t;
  direction : Vec3.t;
  right : Vec3.t;
  up : Vec3.t;
  aperture : float;
  focal_distance : float;
  blur_samples : int;
  blur_samples_min : int;
  blur_thresholds : float array;
  blur_points : float array;
  frame : frame;
  normal : Normal.t option;
}

let deg = Float.pi /. 180.

let frame ~right ~up ~direction ~angle_deg ~v_angle_deg =
  {
    ur = Vec3.normalize right;
    uu = Vec3.normalize up;
    ud = Vec3.normalize direction;
    lr = Vec3.length right;
    lu = Vec3.length up;
    angle = angle_deg *. deg;
    v_angle = v_angle_deg *. deg;
  }

let default =
  let right = Vec3.make 1.33 0. 0. and up = Vec3.unit_y and direction = Vec3.unit_z in
  {
    projection = Perspective;
    location = Vec3.zero;
    direction;
    right;
    up;
    aperture = 0.;
    focal_distance = 1.;
    blur_samples = 0;
    blur_samples_min = 0;
    blur_thresholds = [||];
    blur_points = [||];
    frame = frame ~right ~up ~direction ~angle_deg:90. ~v_angle_deg:180.;
    normal = None;
  }

(* POV-Ray's thresholds for n = 1 .. samples lens rays: the variance of
   the mean must fall under variance x chi2(n) / chi2(samples - 1), the
   chi-square quantiles taken at [confidence] (tracepixel.cpp) *)
let blur_thresholds ~samples ~confidence ~variance =
  if samples <= 1 then Array.make (max samples 0) 0.
  else
    let k = variance /. Chi2.quantile_upper ~df:(float_of_int (samples - 1)) confidence in
    Array.init samples (fun i -> k *. Chi2.quantile_upper ~df:(float_of_int (i + 1)) confidence)

(* Focal blur's lens points. The first seven are the centre and a
   hexagon near the rim (radius 0.95): POV-Ray's confidence test stops
   after them where they all agree, and an edge seen across part of the
   lens is caught best by points spread out to the rim (a ring at 0.866,
   POV-Ray's, and one at 0.95 gave 32.8 and 33.2 dB against a 400-ray
   reference on the clojure-dof seed, one at 0.75 only 30.2). Each later
   point is the centre of the largest hole left, found on a grid fine
   enough for [samples] points (farthest-point sampling): the point of
   the grid farthest from the points before it and from the rim, the rim
   counting double (a point's share of the disc reaches halfway to its
   neighbours but all the way to the rim). Past [exact] points the grid
   would cost too much: random points follow. *)
let blur_points samples =
  let exact = 1024 in
  let p = Array.make (2 * max samples 0) 0. in
  for i = 1 to min 6 (samples - 1) do
    let phi = Float.pi /. 3. *. float_of_int (i - 1) in
    p.(2 * i) <- 0.95 *. Float.cos phi;
    p.((2 * i) + 1) <- 0.95 *. Float.sin phi
  done;
  if samples > 7 then begin
    (* the grid's points in the disc, each with its squared distance to
       the nearest point placed and its distance to the rim (doubled) *)
    let m = max 48 (int_of_float (Float.ceil (2. *. Float.sqrt (float_of_int (min samples exact))))) in
    let h = 1. /. float_of_int m in
    let gx = ref [] in
    for i = -m to m do
      for j = -m to m do
        let x = h *. float_of_int i and y = h *. float_of_int j in
        if (x *. x) +. (y *. y) < 1. then gx := (x, y) :: !gx
      done
    done;
    let g = Array.of_list (List.rev !gx) in
    let near = Array.make (Array.length g) infinity in
    let rim = Array.map (fun (x, y) -> 2. *. (1. -. Float.hypot x y)) g in
    let place i =
      let px = p.(2 * i) and py = p.((2 * i) + 1) in
      Array.iteri
        (fun k (x, y) ->
          let dx = x -. px and dy = y -. py in
          near.(k) <- Float.min near.(k) ((dx *. dx) +. (dy *. dy)))
        g
    in
    for i = 0 to 6 do
      place i
    done;
    let rng = Sampler.create ~seed:0x1e45 ~pixel:0 ~sample:0 in
    for i = 7 to samples - 1 do
      if i < exact then begin
        let best = ref 0 and score = ref neg_infinity in
        Array.iteri
          (fun k d ->
            let s = Float.min (Float.sqrt d) rim.(k) in
            if s > !score then begin
              score := s;
              best := k
            end)
          near;
        let x, y = g.(!best) in
        p.(2 * i) <- x;
        p.((2 * i) + 1) <- y;
        place i
      end
      else begin
        Sampler.reset rng ~seed:0x1e45 ~pixel:i ~sample:0;
        let r = Float.sqrt (Sampler.get rng 0) and phi = 2. *. Float.pi *. Sampler.get rng 1 in
        p.(2 * i) <- r *. Float.cos phi;
        p.((2 * i) + 1) <- r *. Float.sin phi
      end
    done
  end;
  p

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

(* [o] at [loc], [d] the unit vector [a ur + b uu + c ud] *)
let[@inline] aim (k : frame) (loc : Vec3.t) a b c (o : Vec3.m) (d : Vec3.m) =
  Vec3.load o loc;
  Vec3.set d
    ((a *. k.ur.x) +. (b *. k.uu.x) +. (c *. k.ud.x))
    ((a *. k.ur.y) +. (b *. k.uu.y) +. (c *. k.ud.y))
    ((a *. k.ur.z) +. (b *. k.uu.z) +. (c *. k.ud.z));
  Vec3.normalize_m d

(* POV-Ray's cylinder cameras: along the axis the screen is flat (scaled
   by the length of up, resp. right); across it the ray turns by [angle]
   over the image. Types 3 and 4 slide the eye along the axis instead. *)
let cylinder_into n (k : frame) (loc : Vec3.t) sx sy o d =
  let about_up = n = 1 || n = 3 in
  let a = (if about_up then sx else sy) *. k.angle in
  let f = (if about_up then sy else sx) *. if about_up then k.lu else k.lr in
  let s = Float.sin a and c = Float.cos a in
  let bend = if n <= 2 then f else 0. in
  if about_up then aim k loc s bend c o d else aim k loc bend s c o d;
  let slide = f -. bend in
  if slide <> 0. then begin
    let ax = if about_up then k.uu else k.ur in
    Vec3.set o (o.mx +. (slide *. ax.x)) (o.my +. (slide *. ax.y)) (o.mz +. (slide *. ax.z))
  end

(* fisheye and omnimax: the point at polar angle [phi] (cosine [cp], sine
   [sp]) of the image circle looks [theta] away from the direction *)
let[@inline] polar_into k loc cp sp theta o d =
  let s = Float.sin theta in
  aim k loc (cp *. s) (sp *. s) (Float.cos theta) o d

(* POV-Ray's omnimax: the image circle fitted to the frame, rad 1 at 180
   degrees through its polynomial; nothing below 45 degrees under the axis *)
let omnimax_into (k : frame) loc sx sy o d =
  let aspect = k.lr /. k.lu and wide = 1.283458 in
  let x0 = 2. *. sx *. if aspect > wide then aspect /. wide else 1. in
  let y0 =
    if aspect > 1. then (((2. *. sy) -. 1.) /. Float.min aspect wide) +. 1. else 2. *. sy /. aspect
  in
  let rad = Float.sqrt ((x0 *. x0) +. (y0 *. y0)) in
  let cp = if rad = 0. then 1. else x0 /. rad and sp = if rad = 0. then 0. else y0 /. rad in
  let r3 = rad *. rad *. rad in
  let theta = (1.411269 *. rad) -. (0.09439 *. r3) +. (0.25674 *. r3 *. rad *. rad) in
  polar_into k loc cp sp theta o d;
  rad <= 1. && sp *. Float.sin theta >= -.Float.cos theta

let fisheye_into (k : frame) loc sx sy o d =
  let x0 = 2. *. sx *. k.lr and y0 = 2. *. sy *. k.lu in
  let rad = Float.sqrt ((x0 *. x0) +. (y0 *. y0)) in
  let cp = if rad = 0. then 1. else x0 /. rad and sp = if rad = 0. then 0. else y0 /. rad in
  polar_into k loc cp sp (rad *. k.angle /. 2.) o d;
  rad <= 1.

(* [v] turned by [a] about the unit axis [k] (Rodrigues), into [d] *)
let turn_into (v : Vec3.m) (k : Vec3.t) a (d : Vec3.m) =
  let c = Float.cos a and s = Float.sin a in
  let kv = (k.x *. v.mx) +. (k.y *. v.my) +. (k.z *. v.mz) in
  let cx = (k.y *. v.mz) -. (k.z *. v.my)
  and cy = (k.z *. v.mx) -. (k.x *. v.mz)
  and cz = (k.x *. v.my) -. (k.y *. v.mx) in
  let w = kv *. (1. -. c) in
  Vec3.set d ((c *. v.mx) +. (s *. cx) +. (w *. k.x)) ((c *. v.my) +. (s *. cy) +. (w *. k.y))
    ((c *. v.mz) +. (s *. cz) +. (w *. k.z))

(* the projections beyond the two planar ones; the screen point comes in
   [o]'s x and y (two floats passed to a call that is not inlined would be
   boxed) *)
let wide_into c (o : Vec3.m) d =
  let k = c.frame and sx = o.mx and sy = o.my in
  match c.projection with
  | Perspective | Orthographic -> assert false
  | Mesh _ -> false
  | Cylinder n ->
      cylinder_into n k c.location sx sy o d;
      true
  | Fisheye -> fisheye_into k c.location sx sy o d
  | Omnimax -> omnimax_into k c.location sx sy o d
  | Ultra_wide_angle ->
      let x0 = sx *. k.angle and y0 = sy *. k.angle *. k.lu /. k.lr in
      aim k c.location (Float.sin x0) (Float.sin y0) (Float.cos x0 *. Float.cos y0) o d;
      true
  | Panoramic ->
      (* POV-Ray's: the full right, up and direction, not their units *)
      let x0 = (0.5 -. sx) *. Float.pi and y0 = Float.pi *. sy in
      let ty =
        if Float.abs ((Float.pi /. 2.) -. Float.abs y0) < 1e-10 then Float.copy_sign 2e10 y0 else Float.tan y0
      in
      let a = Float.cos x0 and b = Float.sin x0 in
      let r = c.right and u = c.up and w = c.direction in
      Vec3.load o c.location;
      Vec3.set d
        ((a *. r.x) +. (ty *. u.x) +. (b *. w.x))
        ((a *. r.y) +. (ty *. u.y) +. (b *. w.y))
        ((a *. r.z) +. (ty *. u.z) +. (b *. w.z));
      Vec3.normalize_m d;
      true
  | Spherical ->
      (* latitude about right, then longitude about up *)
      Vec3.load d k.ud;
      turn_into d k.ur (-.(sy *. k.v_angle)) o;
      turn_into o k.uu (sx *. k.angle) d;
      Vec3.load o c.location;
      Vec3.normalize_m d;
      true

let[@inline] base_into c sx sy o d =
  match c.projection with
  | Perspective ->
      Vec3.load o c.location;
      span_into c c.direction sx sy true d;
      true
  | Orthographic ->
      span_into c c.location sx sy false o;
      Vec3.load d c.direction;
      Vec3.normalize_m d;
      true
  | _ ->
      Vec3.set o sx sy 0.;
      wide_into c o d

(* the polar angle of (x0, y0) as POV-Ray takes it for a camera normal,
   into [p]'s x, the radius into its y *)
let[@inline] polar (p : Vec3.m) x0 y0 =
  let rad = Float.sqrt ((x0 *. x0) +. (y0 *. y0)) in
  p.mx <- (if rad = 0. then 0. else if x0 < 0. then Float.pi -. Float.asin (y0 /. rad) else Float.asin (y0 /. rad));
  p.my <- rad;
  p.mz <- 0.

(* POV-Ray's point for a camera normal: the screen coordinates as each
   projection has turned them when the ray is made (perspective and
   orthographic: sx, sy; the others: their angles), at z = 0; the screen
   point comes in [p]'s x and y (floats passed to a call not inlined would
   be boxed) *)
let normal_point c (p : Vec3.m) =
  let k = c.frame and sx = p.mx and sy = p.my in
  match c.projection with
  | Perspective | Orthographic | Mesh _ -> Vec3.set p sx sy 0.
  | Cylinder n ->
      if n = 1 || n = 3 then Vec3.set p (sx *. k.angle) (sy *. k.lu) 0.
      else Vec3.set p (sx *. k.lr) (sy *. k.angle) 0.
  | Fisheye ->
      polar p (2. *. sx *. k.lr) (2. *. sy *. k.lu);
      p.my <- p.my *. k.angle /. 2.
  | Omnimax ->
      let aspect = k.lr /. k.lu and wide = 1.283458 in
      let x0 = 2. *. sx *. if aspect > wide then aspect /. wide else 1. in
      let y0 = if aspect > 1. then (((2. *. sy) -. 1.) /. Float.min aspect wide) +. 1. else 2. *. sy /. aspect in
      polar p x0 y0;
      let rad = p.my in
      let r3 = rad *. rad *. rad in
      p.my <- (1.411269 *. rad) -. (0.09439 *. r3) +. (0.25674 *. r3 *. rad *. rad)
  | Ultra_wide_angle -> Vec3.set p (sx *. k.angle) (sy *. k.angle *. k.lu /. k.lr) 0.
  | Panoramic -> Vec3.set p ((0.5 -. sx) *. Float.pi) (Float.pi *. sy) 0.
  | Spherical -> Vec3.set p (sx *. k.angle) (sy *. k.v_angle) 0.

(* the camera normal's scratch: its point and the turned direction *)
type bend = { bp : Vec3.m; bd : Vec3.m }

let bend_key = Scratch.key (fun () -> { bp = Vec3.m (); bd = Vec3.m () })

(* [d] (a unit vector) turned by the camera's normal as a surface normal
   is, at the screen point's [normal_point], as POV-Ray does after the
   ray (and its focal blur) is made *)
let bend nm c (b : bend) (d : Vec3.m) =
  normal_point c b.bp;
  Normal.perturb_m nm b.bp d b.bd;
  Vec3.set d b.bd.mx b.bd.my b.bd.mz;
  Vec3.normalize_m d

(* a camera's normal turns the ray's direction by its pattern at the
   screen point (sx, sy, 0) *)
let[@inline] bend_ray c sx sy d =
  match c.normal with
  | Some nm ->
      let b = Scratch.get bend_key in
      Vec3.set b.bp sx sy 0.;
      bend nm c b d
  | None -> ()

let[@inline] ray_into c sx sy o d =
  let seen = base_into c sx sy o d in
  bend_ray c sx sy d;
  seen

let sees c sx sy = ray_into c sx sy (Vec3.m ()) (Vec3.m ())

let origin c sx sy =
  match c.projection with
  | Perspective -> c.location
  | Orthographic -> span c c.location sx sy false
  | _ ->
      let o = Vec3.m () and d = Vec3.m () in
      ignore (ray_into c sx sy o d);
      Vec3.of_m o

let dir c sx sy =
  match c.projection with
  | Perspective when c.normal = None -> span c c.direction sx sy true
  | Orthographic when c.normal = None -> Vec3.normalize c.direction
  | _ ->
      let o = Vec3.m () and d = Vec3.m () in
      ignore (ray_into c sx sy o d);
      Vec3.of_m d

let ray c sx sy = Ray.make (origin c sx sy) (dir c sx sy)

let[@inline] disc_into c sx sy lx ly (o : Vec3.m) (d : Vec3.m) =
  let seen = base_into c sx sy o d in
  if seen && c.aperture <> 0. then begin
    (* POV-Ray's lens has radius aperture/4 (checked by rendering a point
       light out of focus) *)
    let kc = 0.25 *. c.aperture *. lx and ks = 0.25 *. c.aperture *. ly in
    let rt = c.right and up = c.up and dir = c.direction in
    let kr = Vec3.inv_len rt.x rt.y rt.z and ku = Vec3.inv_len up.x up.y up.z in
    let ox = (kc *. (kr *. rt.x)) +. (ks *. (ku *. up.x))
    and oy = (kc *. (kr *. rt.y)) +. (ks *. (ku *. up.y))
    and oz = (kc *. (kr *. rt.z)) +. (ks *. (ku *. up.z)) in
    let kd = Vec3.inv_len dir.x dir.y dir.z in
    let ax = kd *. dir.x and ay = kd *. dir.y and az = kd *. dir.z in
    let tf = c.focal_distance /. ((d.mx *. ax) +. (d.my *. ay) +. (d.mz *. az)) in
    let fx = o.mx +. (tf *. d.mx) and fy = o.my +. (tf *. d.my) and fz = o.mz +. (tf *. d.mz) in
    Vec3.set o (o.mx +. ox) (o.my +. oy) (o.mz +. oz);
    Vec3.set d (fx -. o.mx) (fy -. o.my) (fz -. o.mz);
    Vec3.normalize_m d
  end;
  bend_ray c sx sy d;
  seen

(* uniform polar mapping of the square onto the disc *)
let[@inline] lens_into c sx sy u v o d =
  let rad = Float.sqrt u and phi = 2. *. Float.pi *. v in
  disc_into c sx sy (rad *. Float.cos phi) (rad *. Float.sin phi) o d

let ray_lens c sx sy u v =
  let o = Vec3.m () and d = Vec3.m () in
  ignore (lens_into c sx sy u v o d);
  Ray.make (Vec3.of_m o) (Vec3.of_m d)
