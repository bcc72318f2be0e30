open Camlray

let float f = Printf.sprintf "%.17g" f

let spline_kw = function
  | Camlray.Prism.Linear -> "linear_spline"
  | Camlray.Prism.Quadratic -> "quadratic_spline"
  | Camlray.Prism.Cubic -> "cubic_spline"
  | Camlray.Prism.Bezier -> "bezier_spline"
let vec (v : Vec3.t) = Printf.sprintf "<%s, %s, %s>" (float v.x) (float v.y) (float v.z)
let rgb (c : Color.t) = Printf.sprintf "rgb <%s, %s, %s>" (float c.r) (float c.g) (float c.b)

let rgbft (c : Color.rgbft) =
  Printf.sprintf "rgbft <%s, %s, %s, %s, %s>" (float c.c.r) (float c.c.g) (float c.c.b)
    (float c.filter) (float c.transmit)

let matrix t =
  let o = Transform.point t Vec3.zero in
  let a = Transform.vector t Vec3.unit_x
  and b = Transform.vector t Vec3.unit_y
  and c = Transform.vector t Vec3.unit_z in
  Printf.sprintf "matrix <%s>"
    (String.concat ", " (List.map float [ a.x; a.y; a.z; b.x; b.y; b.z; c.x; c.y; c.z; o.x; o.y; o.z ]))

let pigment = function
  | Pigment.Solid c -> Printf.sprintf "pigment { %s }" (rgbft c)
  | Pigment.Map _ | Pigment.Blocks _ | Pigment.Image_map _ | Pigment.Average _ | Pigment.Uv _ ->
      invalid_arg "Printer: patterned pigments are not printed"

let finish (f : Finish.t) =
  let r = f.reflection in
  Printf.sprintf
    "finish { ambient %s emission %s diffuse %s, %s brilliance %s phong %s phong_size %s specular %s \
     roughness %s metallic %s reflection { %s, %s fresnel %s falloff %s exponent %s metallic %s } \
     conserve_energy %s%s }"
    (rgb f.ambient) (rgb f.emission) (float f.diffuse) (float f.diffuse_back) (float f.brilliance)
    (float f.phong) (float f.phong_size) (float f.specular) (float f.roughness) (float f.metallic)
    (rgb r.rmin) (rgb r.rmax) (if r.fresnel then "on" else "off") (float r.falloff) (float r.exponent)
    (float r.rmetallic) (if f.conserve_energy then "on" else "off")
    (if f.irid = 0. then ""
     else
       Printf.sprintf " irid { %s thickness %s turbulence %s }" (float f.irid) (float f.irid_thickness)
         (float f.irid_turb))

let layer (l : Texture.layer) = Printf.sprintf "texture { %s %s }" (pigment l.pigment) (finish l.finish)

(* densities print as their colours: patterned ones are not printed, as
   pigments *)
let density = function
  | Pigment.Solid c -> Printf.sprintf " density { %s }" (rgbft c)
  | _ -> invalid_arg "Printer: patterned densities are not printed"

let media (m : Media.t) =
  Printf.sprintf
    "media { emission %s absorption %s%s%s method %d intervals %d samples %d, %d confidence %s variance %s \
     ratio %s jitter %s aa_threshold %s aa_level %d%s }"
    (rgb m.emission) (rgb m.absorption)
    (match m.scattering with
    | None -> ""
    | Some s ->
        Printf.sprintf " scattering { %d, %s eccentricity %s extinction %s }" s.kind (rgb s.color)
          (float s.eccentricity) (float s.extinction))
    (String.concat "" (List.map density m.density))
    m.meth m.intervals m.samples m.samples_max (float m.confidence) (float m.variance) (float m.ratio)
    (float m.jitter) (float m.aa_threshold) m.aa_level
    (if m.collect then "" else " collect off")

let interior (i : Interior.t) =
  Printf.sprintf "interior { ior %s fade_distance %s fade_power %s fade_color %s%s%s }" (float i.ior)
    (float i.fade_distance) (float i.fade_power) (rgb i.fade_color)
    (if i.caustics = 0. then "" else " caustics " ^ float (i.caustics /. 45.))
    (String.concat "" (List.map (fun m -> " " ^ media m) i.media))

(* The light's type words, in an order that reads back to the same
   state: shadowless last (it makes a point light of any type), point_at
   only where it is taken *)
let light_kind (l : Sdl.light) =
  let params radius falloff tightness =
    Printf.sprintf " point_at %s radius %s falloff %s tightness %s" (vec l.point_at) (float radius)
      (float falloff) (float tightness)
  in
  match l.kind with
  | Sdl.Cylinder_light { radius; falloff; tightness } -> " cylinder" ^ params radius falloff tightness
  | Sdl.Spot_light { radius; falloff; tightness } ->
      " spotlight" ^ (if l.parallel then " parallel" else "") ^ params radius falloff tightness
  | Sdl.Point_light ->
      let at = Printf.sprintf " point_at %s" (vec l.point_at) in
      (if l.parallel then " parallel" ^ at
       else if l.shadowless && l.point_at <> Vec3.unit_z then " spotlight" ^ at
       else "")
      ^ if l.shadowless then " shadowless" else ""

(* The text of an object: its head (the keyword, '{' and the shape's
   parameters) and its modifiers, without the closing '}'. *)
(* an object's or a light's photons { } words *)
let photons (p : Photon.flags) =
  let sw w v = if v > 0 then [ w ^ " on" ] else if v < 0 then [ w ^ " off" ] else [] in
  "photons { "
  ^ String.concat " "
      ((if p.target > 0. then [ "target " ^ float p.target ] else [])
      @ sw "refraction" p.refraction @ sw "reflection" p.reflection
      @ (if p.collect then [] else [ "collect off" ])
      @ (if p.pass_through then [ "pass_through" ] else [])
      @ (if p.split_union then [] else [ "split_union off" ])
      @ if p.area_light then [ "area_light" ] else [])
  ^ " }"

let rec parts (o : Sdl.obj) =
  let tex =
    match o.texture with
    | None -> []
    | Some layers -> List.rev_map layer layers (* bottom layer first *)
  in
  let inner =
    match o.inner with
    | None -> []
    | Some layers ->
        (* interior_texture { ... }: each layer's body, bottom first *)
        List.rev_map
          (fun l ->
            let t = layer l in
            "interior_" ^ t)
          layers
  in
  let mods =
    tex
    @ inner
    @ (match o.interior with Some i -> [ interior i ] | None -> [])
    @ (if o.no_shadow then [ "no_shadow" ] else [])
    @ List.filter_map
        (fun (k, w) -> if o.flags land k <> 0 then Some w else None)
        [ (Sdl.no_image, "no_image"); (Sdl.no_reflection, "no_reflection"); (Sdl.double_illuminate, "double_illuminate") ]
    @ (if o.hollow then [ "hollow on" ] else [])
    @ (if o.photon = Photon.none then [] else [ photons o.photon ])
    @ if Transform.is_identity o.xform then [] else [ matrix o.xform ]
  in
  let simple head = (head, mods) in
  match o.shape with
  | Sdl.Light l ->
      ( Printf.sprintf "light_source { %s, %s%s fade_distance %s fade_power %s" (vec l.position)
          (rgb l.color) (light_kind l) (float l.fade_distance) (float l.fade_power)
          ^ (match l.projected_through with Some p -> " projected_through { " ^ obj p ^ " }" | None -> "")
          ^ (if l.media_interaction then "" else " media_interaction off")
          ^ (if l.media_attenuation then " media_attenuation on" else ""),
        (if o.photon = Photon.none then [] else [ photons o.photon ])
        @ if Transform.is_identity o.xform then [] else [ matrix o.xform ] )
  | Sdl.Sphere (c, r) -> simple (Printf.sprintf "sphere { %s, %s" (vec c) (float r))
  | Sdl.Plane (n, d) | Sdl.Unit_plane (n, d) -> simple (Printf.sprintf "plane { %s, %s" (vec n) (float d))
  | Sdl.Box (a, b) -> simple (Printf.sprintf "box { %s, %s" (vec a) (vec b))
  | Sdl.Cone c when c.cylinder ->
      simple
        (Printf.sprintf "cylinder { %s, %s, %s%s" (vec c.base) (vec c.top) (float c.base_r)
           (if c.open_ then " open" else ""))
  | Sdl.Cone c ->
      simple
        (Printf.sprintf "cone { %s, %s, %s, %s%s" (vec c.base) (float c.base_r) (vec c.top)
           (float c.top_r) (if c.open_ then " open" else ""))
  | Sdl.Torus (r1, r2) -> simple (Printf.sprintf "torus { %s, %s" (float r1) (float r2))
  | Sdl.Disc d ->
      simple
        (Printf.sprintf "disc { %s, %s, %s, %s" (vec d.center) (vec d.normal) (float d.radius)
           (float d.hole))
  | Sdl.Triangle (a, b, c) -> simple (Printf.sprintf "triangle { %s, %s, %s" (vec a) (vec b) (vec c))
  | Sdl.Smooth_triangle (a, b, c, na, nb, nc) ->
      simple
        (Printf.sprintf "smooth_triangle { %s, %s, %s, %s, %s, %s" (vec a) (vec na) (vec b) (vec nb)
           (vec c) (vec nc))
  | Sdl.Mesh m ->
      if Array.length m.textures > 0 then invalid_arg "Printer: meshes with textures are not printed";
      let vectors name (a : Float.Array.t) =
        let n = Float.Array.length a / 3 in
        Printf.sprintf "%s { %d%s }" name n
          (String.concat ""
             (List.init n (fun i ->
                  ", " ^ vec (Vec3.make (Float.Array.get a (3 * i)) (Float.Array.get a ((3 * i) + 1))
                               (Float.Array.get a ((3 * i) + 2))))))
      in
      let indices name (a : int array) =
        let n = Array.length a / 3 in
        Printf.sprintf "%s { %d%s }" name n
          (String.concat ""
             (List.init n (fun i -> Printf.sprintf ", <%d, %d, %d>" a.(3 * i) a.((3 * i) + 1) a.((3 * i) + 2))))
      in
      let blocks =
        [ vectors "vertex_vectors" m.verts ]
        @ (if Float.Array.length m.normals > 0 then [ vectors "normal_vectors" m.normals ] else [])
        @ [ indices "face_indices" m.faces ]
        @ (if Array.length m.normal_faces > 0 then [ indices "normal_indices" m.normal_faces ] else [])
      in
      ( "mesh2 { " ^ String.concat " " blocks,
        (match m.inside_vector with Some v -> [ "inside_vector " ^ vec v ] | None -> []) @ mods )
  | Sdl.Algebraic { order = 2; coef = c; quadric = true } ->
      simple
        (Printf.sprintf "quadric { %s, %s, %s, %s" (vec (Vec3.make c.(0) c.(4) c.(7)))
           (vec (Vec3.make c.(1) c.(2) c.(5))) (vec (Vec3.make c.(3) c.(6) c.(8))) (float c.(9)))
  | Sdl.Algebraic a ->
      simple
        (Printf.sprintf "poly { %d, <%s>" a.order (String.concat ", " (Array.to_list (Array.map float a.coef))))
  | Sdl.Text t ->
      let str x = "\"" ^ String.concat "" (List.map (function '"' -> "\\\"" | '\\' -> "\\\\" | c -> String.make 1 c) (List.of_seq (String.to_seq x))) ^ "\"" in
      simple (Printf.sprintf "text { ttf %s %s %s, %s" (str t.font) (str t.chars) (float t.thickness) (vec t.offset))
  | Sdl.Blob (threshold, comps) ->
      let rec comp = function
        | Blob.Sphere { center; radius; strength } ->
            Printf.sprintf "sphere { %s, %s, strength %s }" (vec center) (float radius) (float strength)
        | Blob.Cylinder { a; b; radius; strength } ->
            Printf.sprintf "cylinder { %s, %s, %s, strength %s }" (vec a) (vec b) (float radius) (float strength)
        | Blob.Placed { shape; xform } ->
            let s = comp shape in
            String.sub s 0 (String.length s - 1) ^ matrix xform ^ " }"
      in
      (* the texture after the transformation (which would move it) *)
      let part (c : Sdl.blob_component) =
        let s = comp c.comp in
        match c.ctex with
        | None -> s
        | Some layers ->
            String.sub s 0 (String.length s - 1) ^ String.concat " " (List.rev_map layer layers) ^ " }"
      in
      simple (Printf.sprintf "blob { threshold %s %s" (float threshold) (String.concat " " (List.map part comps)))
  | Sdl.Height_field hf ->
      let src =
        match hf.source with
        | Sdl.Hf_file (kind, file) ->
            (match kind with Some k -> k ^ " " | None -> "") ^ Printf.sprintf "%S" file
        | Sdl.Hf_function (w, h, Some body) -> Printf.sprintf "function %d, %d { %s }" w h body
        | Sdl.Hf_function (w, h, None) -> Printf.sprintf "function %d, %d { 0 /* a pigment function */ }" w h
      in
      simple
        (Printf.sprintf "height_field { %s%s%s" src (if hf.smooth then " smooth" else "")
           (if hf.water <> 0. then " water_level " ^ float hf.water else ""))
  | Sdl.Superellipsoid (e, n) -> simple (Printf.sprintf "superellipsoid { <%s, %s>" (float e) (float n))
  | Sdl.Julia { jc; hypercomplex; cube; max_iteration; precision } ->
      simple
        (Printf.sprintf "julia_fractal { <%s> %s %s max_iteration %d precision %s"
           (String.concat ", " (Array.to_list (Array.map float jc)))
           (if hypercomplex then "hypercomplex" else "quaternion")
           (if cube then "cube" else "sqr") max_iteration (float precision))
  | Sdl.Isosurface i ->
      let params = Fn.params i.fn in
      simple
        (Printf.sprintf "isosurface { function %s{ %s } contained_by { %s } threshold %s accuracy %s max_gradient %s%s%s%s"
           (if params = [ "x"; "y"; "z" ] then "" else "(" ^ String.concat ", " params ^ ") ")
           (Option.value (Fn.source i.fn) ~default:"0")
           (match i.container with
            | Isosurface.Box (a, b) -> Printf.sprintf "box { %s, %s }" (vec a) (vec b)
            | Isosurface.Sphere (c, r) -> Printf.sprintf "sphere { %s, %s }" (vec c) (float r))
           (float i.threshold) (float i.accuracy) (float i.max_gradient)
           (match i.evaluate with
            | Some (a, b, c) -> Printf.sprintf " evaluate %s, %s, %s" (float a) (float b) (float c)
            | None -> "")
           (if i.iso_open then " open" else "")
           (if i.max_trace = max_int then " all_intersections" else Printf.sprintf " max_trace %d" i.max_trace))
  | Sdl.Polygon pts ->
      simple
        (Printf.sprintf "polygon { %d%s" (Array.length pts)
           (String.concat "" (Array.to_list (Array.map (fun p -> ", " ^ vec p) pts))))
  | Sdl.Sor { points; sor_open } ->
      simple
        (Printf.sprintf "sor { %d%s%s" (Array.length points)
           (String.concat "" (Array.to_list (Array.map (fun (x, y) -> Printf.sprintf ", <%s, %s>" (float x) (float y)) points)))
           (if sor_open then " open" else ""))
  | Sdl.Lathe (spline, points) ->
      simple
        (Printf.sprintf "lathe { %s %d%s" (spline_kw spline) (Array.length points)
           (String.concat "" (Array.to_list (Array.map (fun (x, z) -> Printf.sprintf ", <%s, %s>" (float x) (float z)) points))))
  | Sdl.Prism p ->
      let kw = spline_kw in
      let sw = match p.sweep with Prism.Linear_sweep -> "linear_sweep" | Prism.Conic_sweep -> "conic_sweep" in
      simple
        (Printf.sprintf "prism { %s %s %s, %s, %d%s%s" sw (kw p.spline) (float p.height1) (float p.height2)
           (Array.length p.points)
           (String.concat "" (Array.to_list (Array.map (fun (x, z) -> Printf.sprintf ", <%s, %s>" (float x) (float z)) p.points)))
           (if p.no_caps then " open" else ""))
  | Sdl.Csg (k, children) ->
      let kw =
        match k with
        | Sdl.Union -> "union" | Sdl.Intersection -> "intersection" | Sdl.Difference -> "difference"
        | Sdl.Merge -> "merge"
      in
      (kw ^ " { " ^ String.concat " " (List.map obj children), mods)
  | Sdl.Light_group (global, children) ->
      (* a light_group takes no modifiers but transformations: the
         object { } around it takes them all *)
      ( Printf.sprintf "object { light_group { %s%s }" (String.concat " " (List.map obj children))
          (if global then " global_lights on" else ""),
        mods )
  | Sdl.Inverse inner ->
      (* modifiers after 'inverse' apply to the wrapper *)
      let head, inner_mods = parts inner in
      (head, inner_mods @ [ "inverse" ] @ mods)
  | Sdl.Clipped (inner, cs) ->
      let head, inner_mods = parts inner in
      (head, inner_mods @ [ "clipped_by { " ^ String.concat " " (List.map obj cs) ^ " }" ] @ mods)
  | Sdl.Bounded (inner, cs) ->
      let head, inner_mods = parts inner in
      (head, inner_mods @ [ "bounded_by { " ^ String.concat " " (List.map obj cs) ^ " }" ] @ mods)

and obj o =
  let head, mods = parts o in
  String.concat " " ((head :: mods) @ [ "}" ])

let camera_item = function
  | Sdl.Perspective -> "perspective"
  | Sdl.Orthographic -> "orthographic"
  | Sdl.Cylinder_camera n -> Printf.sprintf "cylinder %d" n
  | Sdl.Fisheye -> "fisheye"
  | Sdl.Omnimax -> "omnimax"
  | Sdl.Ultra_wide_angle -> "ultra_wide_angle"
  | Sdl.Panoramic -> "panoramic"
  | Sdl.Spherical_camera -> "spherical"
  | Sdl.Location v -> "location " ^ vec v
  | Sdl.Look_at v -> "look_at " ^ vec v
  | Sdl.Angle a -> "angle " ^ float a
  | Sdl.Angles (h, v) -> "angle " ^ float h ^ ", " ^ float v
  | Sdl.Right v -> "right " ^ vec v
  | Sdl.Up v -> "up " ^ vec v
  | Sdl.Direction v -> "direction " ^ vec v
  | Sdl.Sky v -> "sky " ^ vec v
  | Sdl.Aperture a -> "aperture " ^ float a
  | Sdl.Focal_point v -> "focal_point " ^ vec v
  | Sdl.Blur_samples (0, n) -> Printf.sprintf "blur_samples %d" n
  | Sdl.Blur_samples (m, n) -> Printf.sprintf "blur_samples %d, %d" m n
  | Sdl.Confidence c -> "confidence " ^ float c
  | Sdl.Variance v -> "variance " ^ float v
  | Sdl.Cam_transform t -> matrix t
  (* normals are not printed (as in textures) *)
  | Sdl.Cam_normal _ -> "/* normal { } */"
  | Sdl.Mesh_camera m ->
      Printf.sprintf "mesh_camera { %s %s %s%s%s }" (float (snd m.rays)) (float (snd m.distribution))
        (match m.max_distance with Some x -> float x ^ " " | None -> "")
        (String.concat " " (List.map obj m.meshes))
        (if m.smooth <> None then " smooth" else "")

let global = function
  | Sdl.Assumed_gamma g -> "assumed_gamma " ^ float g
  | Sdl.Max_trace_level n -> Printf.sprintf "max_trace_level %d" n
  | Sdl.Irid_wavelength c -> "irid_wavelength " ^ rgb c
  | Sdl.Adc_bailout a -> "adc_bailout " ^ float a
  | Sdl.Ambient_light c -> "ambient_light " ^ rgb c
  | Sdl.Radiosity r ->
      let b x = if x then "on" else "off" in
      Printf.sprintf
        "radiosity { count %d recursion_limit %d brightness %s error_bound %s nearest_count %d gray_threshold %s \
         pretrace_start %s pretrace_end %s low_error_factor %s minimum_reuse %s maximum_reuse %s adc_bailout %s \
         max_sample %s always_sample %s normal %s media %s }"
        r.count r.recursion_limit (float r.brightness) (float r.error_bound) r.nearest_count (float r.gray_threshold)
        (float r.pretrace_start) (float r.pretrace_end) (float r.low_error_factor) (float r.minimum_reuse)
        (float r.maximum_reuse) (float r.adc_bailout) (float r.max_sample) (b r.always_sample) (b r.normal) (b r.media)
  | Sdl.Noise_generator n -> Printf.sprintf "noise_generator %d" n
  | Sdl.Number_of_waves n -> Printf.sprintf "number_of_waves %d" n
  | Sdl.Photons p ->
      Printf.sprintf
        "photons { spacing %s %sgather %d, %d jitter %s %s%sautostop %s expand_thresholds %s, %d radius %s, %s, %s, %s%s }"
        (float p.spacing) (if p.count > 0 then Printf.sprintf "count %d " p.count else "") p.gather_min p.gather_max
        (float p.jitter)
        (if p.max_trace_level > 0 then Printf.sprintf "max_trace_level %d " p.max_trace_level else "")
        (if p.adc_bailout >= 0. then Printf.sprintf "adc_bailout %s " (float p.adc_bailout) else "")
        (float p.autostop) (float p.expand_tolerance) p.expand_min (float p.radius) (float p.radius_mult)
        (float p.media_radius) (float p.media_mult)
        (if p.media_steps > 0 then Printf.sprintf " media %d, %s" p.media_steps (float p.media_factor) else "")

let item = function
  | Sdl.Object o -> obj o
  | Sdl.Camera (_, items) -> "camera { " ^ String.concat " " (List.map camera_item items) ^ " }"
  | Sdl.Background c -> Printf.sprintf "background { %s }" (rgbft c)
  | Sdl.Global_settings (_, gs) -> "global_settings { " ^ String.concat " " (List.map global gs) ^ " }"
  | Sdl.Sky_sphere _ -> invalid_arg "Printer: sky_sphere is not printed"
  | Sdl.Rainbow _ -> invalid_arg "Printer: rainbow is not printed"
  | Sdl.Media m -> media m
  | Sdl.Fog f ->
      let kind =
        match f.kind with
        | Fog.Constant -> "fog_type 1"
        | Fog.Ground { offset; alt; up } ->
            Printf.sprintf "fog_type 2 fog_offset %s fog_alt %s up %s" (float offset) (float alt) (vec up)
      in
      let turb =
        match f.turbulence with
        | None -> ""
        | Some u ->
            Printf.sprintf " turbulence %s turb_depth %s octaves %d omega %s lambda %s" (vec u.amount)
              (float u.depth) u.octaves (float u.omega) (float u.lambda)
      in
      Printf.sprintf "fog { %s distance %s color %s%s }" kind (float f.distance) (rgbft f.color) turb

let scene (s : Sdl.scene) =
  let version = match s.version with Some v -> Printf.sprintf "#version %s;\n" (float v) | None -> "" in
  version ^ String.concat "\n" (List.map item s.items) ^ "\n"
