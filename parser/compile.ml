open Camlray

module Phys = Hashtbl.Make (struct
  type t = Sdl.mesh

  let equal = ( == )
  let hash = Hashtbl.hash
end)

(* POV-Ray's mesh_camera, checked as POV-Ray's parser checks it (the two
   numbers truncated to integers), given the camera's final location and
   direction (only their z counts) *)
let mesh_camera (m : Sdl.mesh_camera) ~(location : Vec3.t) ~(direction : Vec3.t) =
  let rloc, r = m.rays and dloc, d = m.distribution in
  let rays = if Float.is_finite r && r < 1e9 then Float.to_int r else 0 in
  if rays < 1 then Diag.error rloc "a mesh_camera shoots at least 1 ray per pixel, found %g" r;
  let dist = if Float.is_finite d && Float.abs d < 1e9 then Float.to_int d else -1 in
  let distribution =
    match dist with
    | 0 -> Mesh_camera.Per_mesh
    | 1 -> Mesh_camera.Summed
    | 2 -> Mesh_camera.Side_by_side
    | 3 -> Mesh_camera.Uv_map
    | _ -> Diag.error dloc "mesh_camera distribution type %g: the types are 0 to 3" d
  in
  if (dist = 2 || dist = 3) && rays <> 1 then
    Diag.error rloc "a mesh_camera of distribution type %d shoots 1 ray per pixel, found %d" dist rays;
  Option.iter
    (fun l -> if dist <> 3 then Diag.error l "smooth applies to mesh_camera distribution type 3 only (this is %d)" dist)
    m.smooth;
  let nm = List.length m.meshes in
  if dist = 0 && rays > nm then
    Diag.error rloc "a mesh_camera of distribution type 0 takes ray k of a pixel from mesh k: %d rays per pixel need %d meshes, found %d"
      rays rays nm;
  let meshes = if dist = 3 then [ List.hd m.meshes ] else m.meshes in
  if dist = 3 && nm > 1 then
    Diag.warning (List.nth m.meshes 1).loc "distribution type 3 uses the mesh_camera's first mesh only: this one is ignored";
  (* one preprocessing per declared mesh, however many times it is used
     (POV-Ray's ess scenes place one mesh 100 times) *)
  let seen = Phys.create 8 in
  let faces (o : Sdl.obj) =
    match o.shape with
    | Sdl.Mesh sm -> (
        match Phys.find_opt seen sm with
        | Some f -> f
        | None ->
            let f =
              Mesh_camera.mesh ~uv:(dist = 3) ~verts:sm.verts ~faces:sm.faces ~normals:sm.normals
                ~normal_faces:sm.normal_faces ~uvs:sm.uvs ~uv_faces:sm.uv_faces
            in
            let k = Mesh_camera.dropped f in
            if k > 0 then
              Diag.warning o.loc
                (Printf.sprintf "%d degenerate triangle%s of this camera mesh dropped, as POV-Ray drops them: the faces after them move up" k
                   (if k = 1 then "" else "s"));
            if dist = 3 && not (Mesh_camera.has_uv f) then
              Diag.warning o.loc "this camera mesh has no uv_vectors: distribution type 3 finds no face, the image is black";
            Phys.replace seen sm f;
            f)
    | _ -> Diag.error o.loc "a mesh_camera takes meshes (mesh, mesh2, or object { } of a declared mesh), not other objects"
  in
  let ms = Array.of_list (List.map (fun (o : Sdl.obj) -> (faces o, o.xform)) meshes) in
  Mesh_camera.make ?far:m.max_distance ~rays ~distribution ~smooth:(m.smooth <> None) ~push:location.z
    ~flip:(direction.z < -1e-10) ms

let mesh_camera_at (s : Sdl.scene) =
  let last_camera = List.fold_left (fun acc i -> match i with Sdl.Camera (_, c) -> Some c | _ -> acc) None s.items in
  let kind items =
    List.fold_left
      (fun acc i ->
        match i with
        | Sdl.Mesh_camera m -> Some m.mc_loc
        | Sdl.Orthographic | Sdl.Perspective | Sdl.Cylinder_camera _ | Sdl.Fisheye | Sdl.Omnimax
        | Sdl.Ultra_wide_angle | Sdl.Panoramic | Sdl.Spherical_camera ->
            None
        | _ -> acc)
      None items
  in
  Option.bind last_camera kind

let camera loc items =
  let find f = List.fold_left (fun acc i -> match f i with Some v -> Some v | None -> acc) None items in
  (* the last type named wins; a mesh camera is made below, once its
     location and direction are final *)
  let kind =
    List.fold_left
      (fun acc i ->
        match i with
        | Sdl.Orthographic -> `Projection Camera.Orthographic
        | Sdl.Perspective -> `Projection Camera.Perspective
        | Sdl.Cylinder_camera n -> `Projection (Camera.Cylinder n)
        | Sdl.Fisheye -> `Projection Camera.Fisheye
        | Sdl.Omnimax -> `Projection Camera.Omnimax
        | Sdl.Ultra_wide_angle -> `Projection Camera.Ultra_wide_angle
        | Sdl.Panoramic -> `Projection Camera.Panoramic
        | Sdl.Spherical_camera -> `Projection Camera.Spherical
        | Sdl.Mesh_camera m -> `Mesh m
        | _ -> acc)
      (`Projection Camera.Perspective) items
  in
  let ortho = match kind with `Projection Camera.Orthographic -> true | _ -> false in
  let planar = ortho || match kind with `Projection Camera.Perspective -> true | _ -> false in
  let location = Option.value ~default:Vec3.zero (find (function Sdl.Location v -> Some v | _ -> None)) in
  let dir0 = find (function Sdl.Direction v -> Some v | _ -> None) in
  let up0 = find (function Sdl.Up v -> Some v | _ -> None) in
  let right0 = find (function Sdl.Right v -> Some v | _ -> None) in
  let angles = find (function Sdl.Angle a -> Some (a, a /. 2.) | Sdl.Angles (h, v) -> Some (h, v) | _ -> None) in
  let angle = Option.map fst angles in
  let sky = Option.value ~default:Vec3.unit_y (find (function Sdl.Sky v -> Some v | _ -> None)) in
  let look_at = find (function Sdl.Look_at v -> Some v | _ -> None) in
  let direction = ref (Option.value ~default:Vec3.unit_z dir0) in
  let up = ref (Option.value ~default:Vec3.unit_y up0) in
  let right = ref (Option.value ~default:(Vec3.make 1.33 0. 0.) right0) in
  (* only these two zoom by the angle; the other types turn by it *)
  (match angle with
  | Some a when a > 0. && a < 180. && planar ->
      (* POV-Ray: |right| / tan(angle * M_PI_360) / 2 *)
      let len = Vec3.length !right /. Float.tan (a *. (Float.pi /. 360.)) /. 2. in
      direction := Vec3.scale len (Vec3.normalize !direction)
  | _ -> ());
  (match look_at with
  | Some p ->
      let dl = Vec3.length !direction and ul = Vec3.length !up and rl = Vec3.length !right in
      let handed = Vec3.dot (Vec3.cross !up !direction) !right in
      let d = Vec3.normalize (Vec3.sub p location) in
      let r = Vec3.cross sky d in
      if Vec3.length r > 1e-12 then begin
        let r = Vec3.normalize r in
        (* up from the right vector before its side is chosen; POV-Ray
           keeps that side only for a positive handedness (up along the
           direction, 0, mirrors too) *)
        let u = Vec3.cross d r in
        let r = if handed > 0. then r else Vec3.neg r in
        direction := Vec3.scale dl d;
        right := Vec3.scale rl r;
        up := Vec3.scale ul u
      end
      else begin
        (* looking along the sky vector: POV-Ray warns, keeps the right
           vector's line and turns up to be perpendicular, the side of
           right chosen by the handedness as above (checked with povray
           3.7: a camera above the origin looking down has +x right, +z
           up; with up z and the default direction z, a handedness of 0,
           it is mirrored) *)
        Diag.warning loc
          "the camera looks along its sky vector: the right vector given (or the default) is kept, as POV-Ray does; \
           give a sky vector across the view to choose the picture's up";
        let r = Vec3.normalize !right in
        let u = Vec3.cross d r in
        let r = if handed > 0. then r else Vec3.neg r in
        direction := Vec3.scale dl d;
        right := Vec3.scale rl r;
        up := Vec3.scale ul u
      end
  | None -> ());
  (if ortho && ((up0 = None && right0 = None) || angle <> None) then
     let dist =
       match look_at with
       | Some p -> Vec3.length (Vec3.sub p location)
       | None -> Vec3.length !direction
     in
     let k = dist /. Vec3.length !direction in
     right := Vec3.scale k !right;
     up := Vec3.scale k !up);
  let xf =
    List.fold_left
      (fun acc i -> match i with Sdl.Cam_transform t -> Transform.then_ acc t | _ -> acc)
      Transform.identity items
  in
  let focal =
    match find (function Sdl.Focal_point v -> Some v | _ -> None) with
    | Some fp -> Vec3.dot (Vec3.sub fp location) (Vec3.normalize !direction)
    | None -> Vec3.dot (Vec3.sub Vec3.zero location) (Vec3.normalize !direction)
  in
  (* POV-Ray draws focal blur only when blur_samples is given: without
     it an aperture changes nothing *)
  let blur_samples_min, blur_samples =
    match find (function Sdl.Blur_samples (m, n) -> Some (m, n) | _ -> None) with
    | Some (m, n) -> (max 0 m, max 0 n)
    | None -> (0, 0)
  in
  let aperture =
    match find (function Sdl.Aperture a -> Some a | _ -> None) with
    | Some a when a <> 0. && blur_samples = 0 ->
        Diag.warning loc
          "this camera has an aperture but no blur_samples: POV-Ray draws no focal blur then, nor does \
           camlray (add blur_samples N)";
        0.
    | Some a -> a
    | None -> 0.
  in
  let direction = Transform.vector xf !direction
  and right = Transform.vector xf !right
  and up = Transform.vector xf !up
  and location = Transform.point xf location in
  let projection =
    match kind with
    | `Projection p -> p
    | `Mesh m -> Camera.Mesh (mesh_camera m ~location ~direction)
  in
  {
    Camera.projection;
    location;
    direction;
    right;
    up;
    aperture;
    focal_distance = Float.abs focal;
    blur_samples;
    blur_samples_min;
    blur_points = Camera.blur_points blur_samples;
    blur_thresholds =
      Camera.blur_thresholds ~samples:blur_samples
        ~confidence:(Option.value ~default:0.9 (find (function Sdl.Confidence c -> Some c | _ -> None)))
        ~variance:(Option.value ~default:(1. /. 128.) (find (function Sdl.Variance v -> Some v | _ -> None)));
    frame =
      (* POV-Ray's defaults: 90 degrees; the spherical camera 360 by 180 *)
      (let h, v =
         match (angles, projection) with
         | Some hv, _ -> hv
         | None, Camera.Spherical -> (360., 180.)
         | None, _ -> (90., 45.)
       in
       Camera.frame ~right ~up ~direction ~angle_deg:h ~v_angle_deg:v);
    normal = find (function Sdl.Cam_normal n -> Some n | _ -> None);
  }

(* An area light's axes moved with the light, and POV-Ray's rules for
   circular and orient (parser.cpp: Parse_Light_Source, then
   Post_Process): circular needs more than one sample along each axis (an
   error); orient makes the light circular, unless a size is 1; with
   orient only the first axis's length counts and the sizes should be
   equal (warnings, as POV-Ray's) *)
let area_of (o : Sdl.obj) x (a : Light.area) =
  if a.circular && (a.n1 <= 1 || a.n2 <= 1) then
    Diag.error o.loc "a circular area light must have more than one sample along each axis (found %d, %d)" a.n1 a.n2;
  let axis1 = Transform.vector x a.axis1 and axis2 = Transform.vector x a.axis2 in
  if a.orient then begin
    if not a.circular then
      Diag.warning o.loc
        (if a.n1 <= 1 || a.n2 <= 1 then
           "orient is only used with circular area lights, and a light with one sample along an axis cannot be circular"
         else "orient is only used with circular area lights: this area light is made circular");
    if Float.abs (Vec3.length axis1 -. Vec3.length axis2) > 1e-10 then
      Diag.warning o.loc "with orient, an area light's two axes should be of equal length: only the first axis's is used";
    if a.n1 <> a.n2 then Diag.warning o.loc "with orient, an area light's two sample sizes should be equal"
  end;
  { a with axis1; axis2; circular = a.circular || (a.orient && a.n1 > 1 && a.n2 > 1) }

(* POV-Ray's light as compiled from its type and parallel flag: a
   parallel point light or spotlight is a parallel light (a spotlight's
   cone factor is 1 along its own axis: POV-Ray's parallel spotlight
   lights everything), a cylinder stays one (its rays are parallel
   already) *)
let light (o : Sdl.obj) (l : Sdl.light) projected_through =
  let x = o.xform in
  let point_at = Transform.point x l.point_at in
  let kind =
    match l.kind with
    | Sdl.Cylinder_light { radius; falloff; tightness } -> Light.Cylinder { point_at; radius; falloff; tightness }
    | Sdl.Spot_light _ | Sdl.Point_light when l.parallel -> Light.Parallel { point_at }
    | Sdl.Spot_light { radius; falloff; tightness } -> Light.spot ~point_at ~radius ~falloff ~tightness
    | Sdl.Point_light -> Light.Point
  in
  let position = Transform.point x l.position in
  (match kind with
  | Light.Cylinder _ when Vec3.dist point_at position = 0. ->
      Diag.warning o.loc "a cylinder light whose point_at is its location lights nothing (it has no axis)"
  | _ -> ());
  {
    Light.position;
    color = l.color;
    kind;
    fade_distance = l.fade_distance;
    fade_power = l.fade_power;
    shadowless = l.shadowless;
    media_interaction = l.media_interaction;
    media_attenuation = l.media_attenuation;
    area = Option.map (area_of o x) l.area;
    projected_through;
    photons = o.photon;
  }

let positive (o : Sdl.obj) what r =
  if not (r > 0.) then Diag.error o.loc "%s must be positive, found %g" what r

(* Meshes are built once per declared value: every [object { M }] of a
   declared mesh shares the same triangles and BVH (instancing; [Phys]
   above). *)

let built : Shape.t Phys.t = Phys.create 16
let parts : (int, Sdl.mesh) Hashtbl.t Phys.t = Phys.create 16

(* how BVHs are built in parallel while a scene compiles (see [scene]) *)
let par : (int -> (int -> unit) -> unit) option ref = ref None

(* the scene's adc_bailout, known before its objects are compiled: the
   blob components' textures lighter than it are left out (see [blob]) *)
let bailout = ref Scene.default_settings.adc_bailout

let rec mesh (o : Sdl.obj) (m : Sdl.mesh) =
  match Phys.find_opt built m with
  | Some s -> s
  | None ->
      let s = build_mesh o m in
      Phys.replace built m s;
      s

and build_mesh (o : Sdl.obj) (m : Sdl.mesh) =
  if Array.length m.faces / 3 > 1 lsl 23 then
    Diag.error o.loc "a mesh is limited to 2^23 (8388608) triangles, found %d" (Array.length m.faces / 3);
  let mm =
    Mesh.make ?uv:(if Array.length m.uv_faces = 0 then None else Some (m.uvs, m.uv_faces))
      ~par:!par ~verts:m.verts ~normals:m.normals ~faces:m.faces ~normal_faces:m.normal_faces
      ~inside_vector:m.inside_vector ()
  in
  let n = Array.length m.faces / 3 in
  let dropped = n - Mesh.triangles mm in
  if dropped > 0 then
    Diag.warning o.loc (Printf.sprintf "%d degenerate triangle%s of this mesh ignored" dropped
                          (if dropped = 1 then "" else "s"));
  Shape.Mesh mm

(* The lib shape of a primitive, after checking its parameters. *)
let shape (o : Sdl.obj) =
  match o.shape with
  | Sdl.Sphere (c, r) ->
      positive o "a sphere's radius" r;
      Shape.sphere c r
  | Sdl.Plane (n, d) -> Shape.plane n d
  | Sdl.Unit_plane (n, d) -> Shape.Plane { normal = n; offset = d }
  | Sdl.Box (a, b) -> Shape.box a b
  | Sdl.Cone c ->
      let what = if c.cylinder then "cylinder" else "cone" in
      if Vec3.dist c.base c.top = 0. then Diag.error o.loc "a %s's two end points must differ" what;
      if c.cylinder then positive o "a cylinder's radius" c.base_r
      else if c.base_r < 0. || c.top_r < 0. || (c.base_r = 0. && c.top_r = 0.) then
        Diag.error o.loc "a cone's radii must be >= 0 and not both 0, found %g and %g" c.base_r c.top_r;
      Shape.cone ~open_:c.open_ c.base c.base_r c.top c.top_r
  | Sdl.Torus (r1, r2) ->
      positive o "a torus's major radius" r1;
      positive o "a torus's minor radius" r2;
      Shape.torus r1 r2
  | Sdl.Disc d ->
      if Vec3.length d.normal = 0. then Diag.error o.loc "a disc's normal cannot be zero";
      positive o "a disc's radius" d.radius;
      if d.hole < 0. then Diag.error o.loc "a disc's hole radius cannot be negative, found %g" d.hole;
      if d.hole >= d.radius then Diag.warning o.loc "this disc's hole is as large as the disc: nothing is left";
      Shape.disc ~hole:d.hole d.center d.normal d.radius
  | Sdl.Triangle (a, b, c) ->
      if Vec3.length2 (Vec3.cross (Vec3.sub b a) (Vec3.sub c a)) = 0. then
        Diag.warning o.loc "degenerate triangle (its corners are on one line) ignored";
      Shape.triangle a b c
  | Sdl.Smooth_triangle (a, b, c, na, nb, nc) ->
      if Vec3.length2 (Vec3.cross (Vec3.sub b a) (Vec3.sub c a)) = 0. then
        Diag.warning o.loc "degenerate triangle (its corners are on one line) ignored";
      if Vec3.length na = 0. || Vec3.length nb = 0. || Vec3.length nc = 0. then (
        Diag.warning o.loc "a smooth_triangle normal is zero: the triangle is flat";
        Shape.triangle a b c)
      else Shape.smooth_triangle a na b nb c nc
  | Sdl.Mesh m -> mesh o m
  | Sdl.Algebraic a ->
      if Array.for_all (fun c -> c = 0.) a.coef then Diag.warning o.loc "every coefficient is zero: no surface";
      (* POV-Ray's quadric is inside where its value is <= 0, its poly below 1e-4 *)
      let inside_below = if a.quadric then Some (Float.succ 0.) else None in
      Shape.Algebraic (Algebraic.make ?inside_below a.order a.coef)
  | Sdl.Text t -> Shape.Text t.glyphs
  | Sdl.Blob (threshold, comps) -> Shape.Blob (Blob.make ~threshold (List.map (fun (c : Sdl.blob_component) -> c.comp) comps))
  | Sdl.Superellipsoid (e, n) -> Shape.Superellipsoid (Superellipsoid.make e n)
  | Sdl.Julia { jc; hypercomplex; cube; max_iteration; precision } -> (
      match Julia.make ~c:jc ~hypercomplex ~cube ~max_iteration ~precision with
      | Ok j -> Shape.Julia j
      | Error e -> Diag.error o.loc "julia_fractal: %s" e)
  | Sdl.Height_field hf -> Shape.Height_field (Height_field.place hf.field o.xform)
  | Sdl.Isosurface i ->
      let run = Fn.run i.fn in
      let fn = Isosurface.fn ~slots:(Fn.frame i.fn) ~result:(Fn.out i.fn) (fun s -> run s 0) in
      Shape.Isosurface
        (Isosurface.make ~fn ~container:i.container ~threshold:i.threshold ~accuracy:i.accuracy
           ~max_gradient:i.max_gradient ~open_:i.iso_open ~max_trace:i.max_trace)
  | Sdl.Polygon pts -> (
      match Polygon.make pts with Ok (p, _) -> Shape.Polygon p | Error e -> Diag.error o.loc "polygon: %s" e)
  | Sdl.Sor { points; sor_open } -> (
      match Sor.make ~open_:sor_open points with Ok s -> Shape.Sor s | Error e -> Diag.error o.loc "sor: %s" e)
  | Sdl.Lathe (spline, points) -> (
      match Lathe.make spline points with Ok l -> Shape.Lathe l | Error e -> Diag.error o.loc "lathe: %s" e)
  | Sdl.Prism p -> (
      match Prism.make p.spline p.sweep p.height1 p.height2 ~open_:p.no_caps p.points with
      | Ok pr -> Shape.Prism pr
      | Error e -> Diag.error o.loc "prism: %s" e)
  | Sdl.Csg _ | Sdl.Inverse _ | Sdl.Clipped _ | Sdl.Bounded _ | Sdl.Light _ | Sdl.Light_group _ -> assert false

(* What a CSG node hands down to its children: its world transform, the
   texture and interior for children without one, no_shadow. *)
type ctx = {
  xf : Transform.t;
  tex : Texture.t option;
  inner : Texture.t option;  (** interior_texture, from the parents *)
  inter : Interior.t option;
  no_shadow : bool;
  flags : int;  (** Sdl.no_image, no_reflection, double_illuminate, from the parents *)
  lights : Light.t list ref;  (** where the global lights go *)
  lset : int;  (** the leaves' light set: 0, or a light group's (see [group_sets]) *)
  global : bool option;  (** in a light group: the outermost group's [global_lights] *)
  glights : Light.t list option;  (** in a light group: the lights its objects see *)
  photon : Photon.flags;  (** the parents' photons words, pushed down (they override the children's) *)
}

let top_ctx lights =
  { xf = Transform.identity; tex = None; inner = None; inter = None; no_shadow = false; flags = 0; lights;
    lset = 0; global = None; glights = None; photon = Photon.none }

(* The light sets of the light groups placed so far, last first: whether
   the global lights join, the group's own lights. Set [k] (1-based, in
   placing order) is the [Object.lights] of the group's surfaces. *)
let group_sets : (bool * Light.t list) list ref = ref []

(* Entering a light group (POV-Ray 3.7, measured): its surfaces are lit by
   the group's own light sources (its direct children), not by those of
   a group around it, unless it has none (then they keep the outer
   group's); the outermost group's global_lights decides for all the
   groups inside it. Shadows are not grouped: every object casts them.
   [ctx] is the group's own (its transform applied); the group's lights
   are compiled, the other children returned with their context. *)
let group_ctx (ctx : ctx) compile_light global children =
  let own = ref [] in
  let looks = List.filter_map (fun (c : Sdl.obj) ->
      match c.shape with Sdl.Light _ -> compile_light { ctx with lights = own } c | _ -> None) children in
  let rest = List.filter (fun (c : Sdl.obj) -> match c.shape with Sdl.Light _ -> false | _ -> true) children in
  let mine = match (List.rev !own, ctx.glights) with [], Some outer -> outer | l, _ -> l in
  let global = match ctx.global with Some g -> g | None -> global in
  group_sets := (global, mine) :: !group_sets;
  let ctx' = { ctx with lset = List.length !group_sets; global = Some global; glights = Some mine } in
  (looks, rest, ctx')

(* POV-Ray's double_illuminate, carried by the finishes of a texture *)
let rec illuminate_both (t : Texture.t) =
  List.map
    (fun (l : Texture.layer) ->
      {
        l with
        finish = { l.finish with double_illuminate = true };
        tmap = Option.map (fun (m : Texture.tmap) -> { m with entries = Array.map (fun (v, t) -> (v, illuminate_both t)) m.entries }) l.tmap;
      })
    t

(* The interior an object hands down: its own or its parent's; [hollow]
   (on it, or on a parent, as POV-Ray sets it on a CSG's children) marks it:
   a ray inside only hollow solids sees fog. An object's own interior is
   its own: POV-Ray 3.7 gives every interior { } (even of a declared
   interior) and every copy of a declared object an interior of its own,
   so a ray in one is not taken to be in the other (measured: two nested
   spheres of ior 1.5 with interior { I } refract as separate solids, as
   with two literal interiors); a CSG's interior is one, shared by the
   parts without their own (a ray crossing from one part into another
   leaves it). *)
let interior_of ctx (o : Sdl.obj) =
  let inter = match o.interior with Some i -> Some (Interior.copy i) | None -> ctx.inter in
  let parent_hollow = match ctx.inter with Some (i : Interior.t) -> i.hollow | None -> false in
  if o.hollow || parent_hollow then
    match inter with
    | Some (i : Interior.t) when i.hollow -> inter
    | _ -> Some { (Option.value ~default:Interior.default inter) with hollow = true }
  else inter

let rec obj ctx (o : Sdl.obj) : Object.t option =
  let o = Sdl.transform_obj ctx.xf o in
  let tex = match o.texture with Some _ -> o.texture | None -> ctx.tex in
  let inter = interior_of ctx o in
  let inner = match o.inner with Some _ -> o.inner | None -> ctx.inner in
  let ctx' =
    { ctx with xf = o.xform; tex; inner; inter; no_shadow = ctx.no_shadow || o.no_shadow; flags = ctx.flags lor o.flags;
      photon = Photon.pushed ~parent:ctx.photon o.photon }
  in
  let children l = Array.of_list (List.filter_map (obj ctx') l) in
  match o.shape with
  | Sdl.Light l ->
      (* projected_through: an object of the light's own, in its frame,
         never drawn (its light sources, if any, dropped) *)
      let projected =
        Option.bind l.projected_through (fun p -> obj { ctx' with lights = ref []; no_shadow = true } p)
      in
      ctx.lights := light o l projected :: !(ctx.lights);
      (* looks_like: an ordinary object placed at the light, casting no
         shadow (so that it does not block its own light) *)
      Option.bind l.looks_like (fun (ll : Sdl.obj) ->
          obj { ctx' with no_shadow = true } (Sdl.transform_obj (Transform.translate l.position) ll))
  | Sdl.Csg (op, l) -> (
      let cs = children l in
      match op with
      | Sdl.Union -> Some (Object.union cs)
      | Sdl.Merge -> Some (Object.merge cs)
      | Sdl.Intersection ->
          if Array.length cs = 0 then Diag.error o.loc "an intersection needs at least one object";
          Some (Object.intersection ~frame:o.xform cs)
      | Sdl.Difference ->
          if Array.length cs = 0 then Diag.error o.loc "a difference needs at least one object";
          Some
            (if Array.length cs = 1 then cs.(0)
             else
               Object.intersection ~frame:o.xform
                 (Array.mapi (fun i c -> if i = 0 then c else Object.invert c) cs)))
  | Sdl.Light_group (global, l) ->
      let looks, rest, ctx'' = group_ctx ctx' obj global l in
      let others = List.filter_map (obj ctx'') rest in
      Some (Object.union (Array.of_list (looks @ others)))
  | Sdl.Inverse inner -> Option.map Object.invert (obj ctx' inner)
  | Sdl.Clipped (inner, clips) ->
      let clips = children clips in
      Option.map (fun i -> Object.with_clip ~frame:o.xform i clips) (obj ctx' inner)
  | Sdl.Bounded (inner, bounds) ->
      let bounds = children bounds in
      Option.map (fun i -> Object.with_bound i bounds) (obj ctx' inner)
  | Sdl.Mesh m when Array.length m.textures > 0 && Array.length m.face_textures > 0 ->
      (* mesh2 with a texture_list: one mesh per texture, in a union *)
      let groups = Hashtbl.create 8 in
      Array.iteri (fun i t -> Hashtbl.replace groups t (i :: Option.value ~default:[] (Hashtbl.find_opt groups t)))
        m.face_textures;
      let cache = match Phys.find_opt parts m with
        | Some c -> c
        | None -> let c = Hashtbl.create 8 in Phys.replace parts m c; c in
      let part t faces_idx =
        let pick a = if Array.length a = 0 then a else
            Array.concat (List.rev_map (fun i -> Array.sub a (3 * i) 3) faces_idx) in
        let m' = match Hashtbl.find_opt cache t with
          | Some m' -> m'
          | None ->
              let m' = { m with faces = pick m.faces; normal_faces = pick m.normal_faces; uv_faces = pick m.uv_faces;
                                face_textures = [||] } in
              Hashtbl.replace cache t m';
              m' in
        (* the list's textures were written in the mesh's own space: they
           move with it, as a texture given to the object does *)
        let texture =
          if t >= 0 && t < Array.length m.textures then Some (Texture.transform o.xform m.textures.(t)) else tex
        in
        leaf ctx' { o with shape = Sdl.Mesh m' } texture inter
      in
      Some (Object.union (Array.of_list (Hashtbl.fold (fun t f acc -> part t f :: acc) groups [])))
  | Sdl.Blob (threshold, comps) when List.exists (fun (c : Sdl.blob_component) -> c.ctex <> None) comps ->
      Some (blob ctx' o tex inter threshold comps)
  | _ -> Some (leaf ctx' o tex inter)

(* a texture as a leaf takes it: shared, lit from behind when asked *)
and leaf_texture ctx tex =
  let t = match tex with Some t -> Shapes.share_texture t | None -> Texture.default in
  if ctx.flags land Sdl.double_illuminate <> 0 then illuminate_both t else t

and leaf ctx o tex inter =
  let texture = leaf_texture ctx tex in
  let interior = Option.value ~default:Interior.default inter in
  let back = Option.map (fun t -> leaf_texture ctx (Some t)) ctx.inner in
  Object.make ~xform:o.xform ~texture ?back ~interior ~no_shadow:ctx.no_shadow ~lights:ctx.lset ~photon:ctx.photon (shape o)

(* A blob whose components have textures of their own: POV-Ray shades
   each component's (the blob's for those without), weighed by its share
   of the fields at the point, and takes no interior_texture. Component
   textures are in the blob's space: they move with it. *)
and blob ctx o tex inter threshold comps =
  let b = Blob.make ~threshold (List.map (fun (c : Sdl.blob_component) -> c.comp) comps) in
  let own = leaf_texture ctx tex in
  let textures =
    List.map
      (fun (c : Sdl.blob_component) ->
        match c.ctex with Some t -> leaf_texture ctx (Some (Texture.transform o.xform t)) | None -> own)
      comps
  in
  let texture = [ Texture.blob_field b ~cut:!bailout o.xform (Array.of_list textures) ] in
  let interior = Option.value ~default:Interior.default inter in
  Object.make ~xform:o.xform ~texture ~interior ~no_shadow:ctx.no_shadow ~lights:ctx.lset ~photon:ctx.photon (Shape.Blob b)

(* An object compiled on its own while the scene is still being read
   (POV-Ray's trace(), inside(), min_extent() and max_extent() ask
   declared objects): its lights are dropped. *)
let standalone (o : Sdl.obj) =
  let ctx = top_ctx (ref []) in
  let sets = !group_sets in
  Fun.protect ~finally:(fun () -> group_sets := sets) @@ fun () ->
  Fun.protect ~finally:(fun () -> Phys.reset built; Phys.reset parts) (fun () -> obj ctx o)

(* Top-level unions (not clipped, not inverted) are flattened into the
   scene's BVH: same surfaces, same textures. *)
let rec top ctx (o : Sdl.obj) acc =
  let inside () =
    let o' = Sdl.transform_obj ctx.xf o in
    let tex = match o'.texture with Some _ -> o'.texture | None -> ctx.tex in
    let inter = interior_of ctx o' in
    let inner = match o'.inner with Some _ -> o'.inner | None -> ctx.inner in
    { ctx with xf = o'.xform; tex; inner; inter; no_shadow = ctx.no_shadow || o'.no_shadow; flags = ctx.flags lor o'.flags;
      photon = Photon.pushed ~parent:ctx.photon o'.photon }
  in
  match o.shape with
  | Sdl.Csg (Sdl.Union, l) when not ((Photon.pushed ~parent:ctx.photon o.photon).target > 0. && not o.photon.split_union) ->
      (* (a target union with split_union off is shot at as one) *)
      let ctx' = inside () in
      List.fold_left (fun acc c -> top ctx' c acc) acc l
  | Sdl.Light_group (global, l) ->
      (* flattened like a union: its objects carry their light set *)
      let ctx' = inside () in
      let looks, rest, ctx'' = group_ctx ctx' obj global l in
      let acc = List.fold_left (fun acc x -> (x, ctx'.flags) :: acc) acc looks in
      List.fold_left (fun acc c -> top ctx'' c acc) acc rest
  | _ -> ( match obj ctx o with Some x -> (x, ctx.flags lor o.flags) :: acc | None -> acc)

let rec scene ?par:p (s : Sdl.scene) =
  par := p;
  Fun.protect
    ~finally:(fun () ->
      par := None;
      bailout := Scene.default_settings.adc_bailout;
      Phys.reset built;
      Phys.reset parts;
      Shapes.forget_textures ())
    (fun () -> scene_ s)

and scene_ (s : Sdl.scene) =
  try
    let objects = ref [] and lights = ref [] and cams = ref [] in
    let background = ref Color.black in
    let sky = ref Sky.none and fog = ref [] and media = ref [] in
    let rainbows = ref [] in
    group_sets := [];
    bailout :=
      List.fold_left
        (fun b -> function
          | Sdl.Global_settings (_, gs) ->
              List.fold_left (fun b -> function Sdl.Adc_bailout a -> a | _ -> b) b gs
          | _ -> b)
        Scene.default_settings.adc_bailout s.items;
    (* the last noise_generator of the scene's global_settings, wherever it
       is, serves every pattern naming none (POV-Ray's scene setting);
       without one, the scene's language version's: 1 below 3.5 (a
       #version 3.1 scene renders with the original noise), else 2 *)
    Pattern.scene_noise_generator :=
      List.fold_left
        (fun g -> function
          | Sdl.Global_settings (_, gs) -> List.fold_left (fun g -> function Sdl.Noise_generator n -> n | _ -> g) g gs
          | _ -> g)
        (match s.version with Some v -> Defaults.noise_for_version v | None -> 2)
        s.items;
    (* and the last number_of_waves, the number of wave sources of every
       ripples and waves (POV-Ray's scene setting, 10 by default) *)
    Pattern.set_number_of_waves
      (List.fold_left
         (fun k -> function
           | Sdl.Global_settings (_, gs) -> List.fold_left (fun k -> function Sdl.Number_of_waves n -> n | _ -> k) k gs
           | _ -> k)
         10 s.items);
    let settings = ref Scene.default_settings in
    let gamma = ref None in
    List.iter
      (function
        | Sdl.Object o ->
            objects := top (top_ctx lights) o !objects
        | Sdl.Sky_sphere k -> sky := k
        | Sdl.Fog f -> fog := f :: !fog
        | Sdl.Rainbow r -> rainbows := r :: !rainbows
        | Sdl.Media m -> media := m :: !media
        | Sdl.Camera (l, c) -> cams := (l, c) :: !cams
        | Sdl.Background c -> background := c.c
        | Sdl.Global_settings (_, gs) ->
            List.iter
              (function
                | Sdl.Assumed_gamma g -> gamma := Some g
                | Sdl.Max_trace_level n ->
                    settings := { !settings with max_trace_level = max 1 (min 256 n) }
                | Sdl.Adc_bailout a -> settings := { !settings with adc_bailout = a }
                | Sdl.Ambient_light c -> settings := { !settings with ambient_light = c }
                | Sdl.Irid_wavelength c -> settings := { !settings with irid_wavelength = c }
                | Sdl.Radiosity r -> settings := { !settings with radiosity = Some r }
                | Sdl.Photons p -> settings := { !settings with photons = Some p }
                | Sdl.Noise_generator _ | Sdl.Number_of_waves _ -> ())
              gs)
      s.items;
    let v37 = match s.version with Some v -> v >= 3.7 | None -> false in
    let encoding =
      match (v37, !gamma) with
      | _, Some g when Float.abs (g -. 1.) < 1e-6 -> Image.Srgb
      | _, Some g when g > 0. -> Image.Gamma_srgb g
      | true, _ -> Image.Srgb
      | false, _ -> Image.Identity
    in
    let camera = match !cams with (l, c) :: _ -> camera l c | [] -> Camera.default in
    let flagged = Array.of_list (List.rev !objects) in
    let objects = Array.map fst flagged in
    let accel = Scene.accelerate ?par:!par objects in
    let hidden = Array.map (fun (_, f) -> f land (Sdl.no_image lor Sdl.no_reflection lor Sdl.no_radiosity)) flagged in
    let lights = Array.of_list (List.rev !lights) in
    let s =
      {
        Scene.objects;
        accel;
        all = accel;
        views = { image = None; reflected = None; gather = None };
        lights;
        light_sets =
          Array.append [| lights |]
            (Array.of_list
               (List.rev_map (fun (g, own) -> Array.of_list ((if g then Array.to_list lights else []) @ own)) !group_sets));
        camera;
        background = !background;
        sky = { !sky with legacy = not v37 };
        fog = List.rev !fog;
        rainbows = List.rev !rainbows;
        atmosphere = Scene.atmosphere (List.rev !media);
        settings =
          { !settings with encoding; legacy_alpha = not v37;
            radiosity =
              Option.map (fun (r : Radiosity.t) -> { r with keep_ambient = not v37; cache = Radiosity.new_cache () })
                !settings.radiosity };
      }
    in
    Ok (if Array.exists (fun f -> f <> 0) hidden || s.settings.radiosity <> None then Scene.hide s hidden else s)
  with Diag.Error d -> Error d
