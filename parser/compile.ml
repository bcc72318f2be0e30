open Camlray

let camera items =
  let find f = List.fold_left (fun acc i -> match f i with Some v -> Some v | None -> acc) None items in
  let ortho =
    List.fold_left
      (fun acc i -> match i with Sdl.Orthographic -> true | Sdl.Perspective -> false | _ -> acc)
      false items
  in
  let location = Option.value ~default:Vec3.zero (find (function Sdl.Location v -> Some v | _ -> None)) in
  let dir0 = find (function Sdl.Direction v -> Some v | _ -> None) in
  let up0 = find (function Sdl.Up v -> Some v | _ -> None) in
  let right0 = find (function Sdl.Right v -> Some v | _ -> None) in
  let angle = find (function Sdl.Angle a -> Some a | _ -> None) in
  let sky = Option.value ~default:Vec3.unit_y (find (function Sdl.Sky v -> Some v | _ -> None)) in
  let look_at = find (function Sdl.Look_at v -> Some v | _ -> None) in
  let direction = ref (Option.value ~default:Vec3.unit_z dir0) in
  let up = ref (Option.value ~default:Vec3.unit_y up0) in
  let right = ref (Option.value ~default:(Vec3.make 1.33 0. 0.) right0) in
  (match angle with
  | Some a when a > 0. && a < 180. ->
      let len = Vec3.length !right /. (2. *. Float.tan (a *. Float.pi /. 360.)) in
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
        let r = if handed < 0. then Vec3.neg r else r in
        direction := Vec3.scale dl d;
        right := Vec3.scale rl r;
        up := Vec3.scale ul (Vec3.cross d (Vec3.normalize r))
      end
      else direction := Vec3.scale dl d
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
  {
    Camera.projection = (if ortho then Camera.Orthographic else Camera.Perspective);
    location = Transform.point xf location;
    direction = Transform.vector xf !direction;
    right = Transform.vector xf !right;
    up = Transform.vector xf !up;
    aperture = Option.value ~default:0. (find (function Sdl.Aperture a -> Some a | _ -> None));
    focal_distance = Float.abs focal;
    blur_samples = Option.value ~default:0 (find (function Sdl.Blur_samples n -> Some n | _ -> None));
  }

let light (o : Sdl.obj) (l : Sdl.light) =
  let x = o.xform in
  let kind =
    match l.kind with
    | Light.Point -> Light.Point
    | Light.Spot s -> Light.Spot { s with point_at = Transform.point x s.point_at }
    | Light.Parallel p -> Light.Parallel { point_at = Transform.point x p.point_at }
  in
  {
    Light.position = Transform.point x l.position;
    color = l.color;
    kind;
    fade_distance = l.fade_distance;
    fade_power = l.fade_power;
    shadowless = l.shadowless;
    area =
      Option.map
        (fun (a : Light.area) ->
          { a with axis1 = Transform.vector x a.axis1; axis2 = Transform.vector x a.axis2 })
        l.area;
  }

let shape (o : Sdl.obj) =
  match o.shape with
  | Sdl.Sphere (c, r) ->
      if r <= 0. then Diag.error o.loc "a sphere's radius must be positive, found %g" r;
      Shape.sphere c r
  | Sdl.Plane (n, d) -> Shape.plane n d
  | Sdl.Light _ -> assert false

let scene (s : Sdl.scene) =
  try
    let objects = ref [] and lights = ref [] and cams = ref [] in
    let background = ref Color.black in
    let sky = ref Sky.none in
    let add_object (o : Sdl.obj) =
      let texture = match o.texture with Some t -> t | None -> Texture.default in
      let interior = Option.value ~default:Interior.default o.interior in
      objects :=
        Object.make ~xform:o.xform ~texture ~interior ~no_shadow:o.no_shadow (shape o) :: !objects
    in
    let settings = ref Scene.default_settings in
    let gamma = ref None in
    List.iter
      (function
        | Sdl.Object ({ shape = Sdl.Light l; _ } as o) ->
            lights := light o l :: !lights;
            (* looks_like: an ordinary object at the light, casting no shadow *)
            Option.iter
              (fun (ll : Sdl.obj) ->
                let at = Transform.then_ (Transform.translate l.position) o.xform in
                add_object { (Sdl.transform_obj at ll) with no_shadow = true })
              l.looks_like
        | Sdl.Object o -> add_object o
        | Sdl.Sky_sphere k -> sky := k
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
                | Sdl.Noise_generator _ | Sdl.Number_of_waves _ -> ())
              gs)
      s.items;
    let v37 = match s.version with Some v -> v >= 3.7 | None -> false in
    let encoding =
      match (v37, !gamma) with
      | true, _ -> Image.Srgb
      | false, Some g when Float.abs (g -. 1.) < 1e-6 -> Image.Srgb
      | false, _ -> Image.Identity
    in
    let camera = match !cams with (_, c) :: _ -> camera c | [] -> Camera.default in
    Ok
      {
        Scene.objects = Array.of_list (List.rev !objects);
        lights = Array.of_list (List.rev !lights);
        camera;
        background = !background;
        sky = !sky;
        settings = { !settings with encoding; legacy_alpha = not v37 };
      }
  with Diag.Error d -> Error d
