(* Top-level scene items: objects, camera, background, global settings. *)
(* (the OCaml header, opening Camlray and Gram, is in grammar_lang.mly) *)

%token CAMERA PERSPECTIVE ORTHOGRAPHIC FISHEYE OMNIMAX ULTRA_WIDE_ANGLE PANORAMIC LOCATION LOOK_AT ANGLE RIGHT UP DIRECTION SKY
%token APERTURE FOCAL_POINT BLUR_SAMPLES MESH_CAMERA
%token BACKGROUND GLOBAL_SETTINGS ASSUMED_GAMMA MAX_TRACE_LEVEL ADC_BAILOUT AMBIENT_LIGHT IRID_WAVELENGTH
%token FOG FOG_TYPE FOG_OFFSET FOG_ALT TURB_DEPTH DISTANCE
%token RAINBOW WIDTH ARC_ANGLE FALLOFF_ANGLE
%token RADIOSITY PHOTONS
%token <string> PHOTON_WORD
%token <string> RAD_WORD RAD_FILE

%start <Sdl.item list> scene

%%

%public scene: items = list(item) EOF { items }

%public item:
  | o = object_ { Defaults.mark_item (); Budget.place o; Sdl.Object (Shapes.default_texture o) }
  | CAMERA LBRACE c = camera_body RBRACE { Defaults.mark_item (); Sdl.Camera (loc $loc, c) }
  | BACKGROUND LBRACE c = color_value RBRACE
      { Sdl.Background (Value.to_color (loc $loc(c)) c) }
  | GLOBAL_SETTINGS LBRACE g = list(global_item) RBRACE { Sdl.Global_settings (loc $loc, g) }
  (* atmospheric media: all space outside non-hollow objects *)
  | MEDIA LBRACE m = media_body RBRACE { Sdl.Media m }
  | FOG LBRACE fs = list(fog_item) RBRACE
      { Sdl.Fog (Fogdesc.fog (loc $loc) (List.fold_left (fun d f -> f d) Fogdesc.empty fs)) }

  | RAINBOW LBRACE rs = list(rainbow_item) RBRACE
      { Sdl.Rainbow (Gram.rainbow (loc $loc) rs) }

(* POV-Ray's rainbow: angle and width in degrees, the colour map read
   across the band *)
rainbow_item:
  | ANGLE e = param { `Angle (fl $loc(e) e) }
  | WIDTH e = param { `Width (fl $loc(e) e) }
  | DISTANCE e = param { `Distance (fl $loc(e) e) }
  | JITTER e = param { `Jitter (fl $loc(e) e) }
  | DIRECTION e = param { `Direction (loc $loc(e), v3 $loc(e) e) }
  | UP e = param { `Up (loc $loc(e), v3 $loc(e) e) }
  | ARC_ANGLE e = param { `Arc (loc $loc(e), fl $loc(e) e) }
  | FALLOFF_ANGLE e = param { `Falloff (loc $loc(e), fl $loc(e) e) }
  | COLOR_MAP LBRACE m = color_map_body RBRACE { `Map m }

fog_item:
  | v = param { Fogdesc.value (loc $loc(v)) v }
  | COLOR v = param ms = list(channel)
      { Fogdesc.color (Value.to_color (loc $loc(v)) (List.fold_left (fun v (l, c, x) -> Value.set_channel l v c x) v ms)) }
  | DISTANCE e = param { Fogdesc.distance (fl $loc(e) e) }
  | FOG_TYPE e = param { Fogdesc.kind (loc $loc(e)) (Value.to_int (loc $loc(e)) e) }
  | FOG_OFFSET e = param { Fogdesc.offset (fl $loc(e) e) }
  | FOG_ALT e = param { Fogdesc.alt (fl $loc(e) e) }
  | UP e = param { Fogdesc.up (v3 $loc(e) e) }
  | TURBULENCE e = param { Fogdesc.turbulence (v3 $loc(e) e) }
  | TURB_DEPTH e = param { Fogdesc.turb_depth (fl $loc(e) e) }
  | OCTAVES e = param { Fogdesc.octaves (loc $loc(e)) (Value.to_int (loc $loc(e)) e) }
  | OMEGA e = param { Fogdesc.omega (fl $loc(e) e) }
  | LAMBDA e = param { Fogdesc.lambda (fl $loc(e) e) }
  | t = transformation { Fogdesc.transform t }

%public camera_body:
  | c = ioption(CAMERA_ID) items = list(camera_item)
      { (match c with Some c -> c | None -> []) @ items }

%public camera_item:
  | PERSPECTIVE { Sdl.Perspective }
  | ORTHOGRAPHIC { Sdl.Orthographic }
  | FISHEYE { Sdl.Fisheye }
  | OMNIMAX { Sdl.Omnimax }
  | ULTRA_WIDE_ANGLE { Sdl.Ultra_wide_angle }
  | PANORAMIC { Sdl.Panoramic }
  | SPHERICAL { Sdl.Spherical_camera }
  | LOCATION e = param { Sdl.Location (v3 $loc(e) e) }
  | LOOK_AT e = param { Sdl.Look_at (v3 $loc(e) e) }
  | ANGLE e = param { Sdl.Angle (fl $loc(e) e) }
  | ANGLE e = param COMMA f = param { Sdl.Angles (fl $loc(e) e, fl $loc(f) f) }
  | RIGHT e = param { Sdl.Right (v3 $loc(e) e) }
  | UP e = param { Sdl.Up (v3 $loc(e) e) }
  | DIRECTION e = param { Sdl.Direction (v3 $loc(e) e) }
  | SKY e = param { Sdl.Sky (v3 $loc(e) e) }
  | APERTURE e = param { Sdl.Aperture (fl $loc(e) e) }
  | FOCAL_POINT e = param { Sdl.Focal_point (v3 $loc(e) e) }
  | BLUR_SAMPLES e = param { Sdl.Blur_samples (0, Value.to_int (loc $loc(e)) e) }
  | BLUR_SAMPLES e = param COMMA f = param
      { Sdl.Blur_samples (Value.to_int (loc $loc(e)) e, Value.to_int (loc $loc(f)) f) }
  (* POV-Ray's confidence test, which stops a pixel's lens rays early *)
  | CONFIDENCE e = param
      { let c = fl $loc(e) e in
        if not (c > 0. && c < 1.) then
          Diag.error (loc $loc(e)) "confidence %g: a probability strictly between 0 and 1 is needed" c;
        Sdl.Confidence c }
  | VARIANCE e = param { Sdl.Variance (fl $loc(e) e) }
  | t = transformation { Sdl.Cam_transform t }
  (* camera words camlray knows elsewhere, named when met here *)
  | CYLINDER e = param
      { let n = Value.to_int (loc $loc(e)) e in
        if n < 1 || n > 4 then
          Diag.error (loc $loc(e)) "cylinder camera type %d: the types are 1 to 4" n;
        Sdl.Cylinder_camera n }
  (* POV-Ray's mesh camera: rays per pixel, the distribution type, an
     optional maximum distance, the meshes, smooth (checked when the
     scene is compiled) *)
  | MESH_CAMERA LBRACE r = param COMMA? d = param COMMA? x = ioption(terminated(param, ioption(COMMA)))
    ms = nonempty_list(object_) s = ioption(SMOOTH) RBRACE
      { Sdl.Mesh_camera
          { mc_loc = loc $loc; rays = (loc $loc(r), fl $loc(r) r); distribution = (loc $loc(d), fl $loc(d) d);
            max_distance = Option.map (fun x -> fl $loc(x) x) x; meshes = ms;
            smooth = Option.map (fun () -> loc $loc(s)) s } }
  (* turns the rays' directions as a surface normal is turned *)
  | NORMAL LBRACE n = normal_body RBRACE
      { match n with
        | Some n when Normal.uses_uv n ->
            (* there is no surface: POV-Ray 3.7 crashes on it *)
            Diag.error (loc $loc(n)) "a camera's normal cannot be uv-mapped (it has no surface to take u and v from)"
        | Some n -> Sdl.Cam_normal n
        | None -> Sdl.Cam_transform Transform.identity }

%public global_item:
  | ASSUMED_GAMMA e = param
      { let g = fl $loc(e) e in
        (* the working gamma from here on: sRGB and image colours read
           later are carried into it *)
        if g > 0. then Value.working_gamma := g;
        Sdl.Assumed_gamma g }
  | MAX_TRACE_LEVEL e = param { Sdl.Max_trace_level (Value.to_int (loc $loc(e)) e) }
  | ADC_BAILOUT e = param { Sdl.Adc_bailout (fl $loc(e) e) }
  | AMBIENT_LIGHT c = color_value { Sdl.Ambient_light (Value.to_rgb (loc $loc(c)) c) }
  | IRID_WAVELENGTH c = color_value { Sdl.Irid_wavelength (Value.to_rgb (loc $loc(c)) c) }
  | RADIOSITY LBRACE rs = list(rad_item) RBRACE { Sdl.Radiosity (Gram.radiosity rs) }
  | ps = photons_block { Sdl.Photons (Gram.photons ps) }

(* photons { ... }: global_settings', an object's or a light's, told
   apart by Gram; a word and its values (on/off may stand alone) *)
%public photons_block:
  | PHOTONS LBRACE ps = list(photon_item) RBRACE { ps }

photon_item:
  | w = photon_word v = ioption(param) m = list(preceded(COMMA, param))
      { (loc $loc(w), w, List.map (fun v -> (loc $loc(v), v)) (Option.to_list v @ m)) }
  | w = RAD_FILE s = string_arg { (loc $loc(w), w, [ (loc $loc(s), Value.String s) ]) }

photon_word:
  | w = PHOTON_WORD { w }
  | w = RAD_WORD { w }
  | MEDIA { "media" }
  | JITTER { "jitter" }
  | MAX_TRACE_LEVEL { "max_trace_level" }
  | ADC_BAILOUT { "adc_bailout" }
  | RADIUS { "radius" }
  | REFLECTION { "reflection" }
  | AREA_LIGHT { "area_light" }

(* a radiosity block's word and its values (on/off words may stand
   alone): global_settings' or an object's, told apart by Gram *)
%public rad_item:
  | w = RAD_WORD v = ioption(param) m = ioption(preceded(COMMA, param))
      { (loc $loc(w), w, Option.map (fun v -> (loc $loc(v), v)) v, Option.map (fun m -> (loc $loc(m), m)) m) }
  | NORMAL v = ioption(param) { (loc $loc, "normal", Option.map (fun v -> (loc $loc(v), v)) v, None) }
  | MEDIA v = ioption(param) { (loc $loc, "media", Option.map (fun v -> (loc $loc(v), v)) v, None) }
  | BRILLIANCE v = ioption(param) { (loc $loc, "brilliance", Option.map (fun v -> (loc $loc(v), v)) v, None) }
  | ADC_BAILOUT v = param { (loc $loc, "adc_bailout", Some (loc $loc(v), v), None) }
  | w = RAD_FILE s = string_arg { (loc $loc, w, Some (loc $loc(s), Value.String s), None) }
