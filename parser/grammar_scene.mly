(* Top-level scene items: objects, camera, background, global settings. *)
(* (the OCaml header, opening Camlray and Gram, is in grammar_lang.mly) *)

%token CAMERA PERSPECTIVE ORTHOGRAPHIC LOCATION LOOK_AT ANGLE RIGHT UP DIRECTION SKY
%token APERTURE FOCAL_POINT BLUR_SAMPLES
%token BACKGROUND GLOBAL_SETTINGS ASSUMED_GAMMA MAX_TRACE_LEVEL ADC_BAILOUT AMBIENT_LIGHT

%start <Sdl.item list> scene

%%

%public scene: items = list(item) EOF { items }

%public item:
  | o = object_ { Defaults.mark_item (); Budget.place o; Sdl.Object (Shapes.default_texture o) }
  | CAMERA LBRACE c = camera_body RBRACE { Defaults.mark_item (); Sdl.Camera (loc $loc, c) }
  | BACKGROUND LBRACE c = color_value RBRACE
      { Sdl.Background (Value.to_color (loc $loc(c)) c) }
  | GLOBAL_SETTINGS LBRACE g = list(global_item) RBRACE { Sdl.Global_settings (loc $loc, g) }

%public camera_body:
  | c = ioption(CAMERA_ID) items = list(camera_item)
      { (match c with Some c -> c | None -> []) @ items }

%public camera_item:
  | PERSPECTIVE { Sdl.Perspective }
  | ORTHOGRAPHIC { Sdl.Orthographic }
  | LOCATION e = param { Sdl.Location (v3 $loc(e) e) }
  | LOOK_AT e = param { Sdl.Look_at (v3 $loc(e) e) }
  | ANGLE e = param { Sdl.Angle (fl $loc(e) e) }
  | RIGHT e = param { Sdl.Right (v3 $loc(e) e) }
  | UP e = param { Sdl.Up (v3 $loc(e) e) }
  | DIRECTION e = param { Sdl.Direction (v3 $loc(e) e) }
  | SKY e = param { Sdl.Sky (v3 $loc(e) e) }
  | APERTURE e = param { Sdl.Aperture (fl $loc(e) e) }
  | FOCAL_POINT e = param { Sdl.Focal_point (v3 $loc(e) e) }
  | BLUR_SAMPLES e = param { Sdl.Blur_samples (Value.to_int (loc $loc(e)) e) }
  | t = transformation { Sdl.Cam_transform t }
  (* camera words camlray knows elsewhere, named when met here *)
  | CYLINDER { Diag.error (loc $loc) "cylinder (a camera type) is not supported by camlray" }
  | SPHERICAL { Diag.error (loc $loc) "spherical (a camera type) is not supported by camlray" }
  | NORMAL { Diag.error (loc $loc) "normal in a camera is not supported by camlray" }

%public global_item:
  | ASSUMED_GAMMA e = param { Sdl.Assumed_gamma (fl $loc(e) e) }
  | MAX_TRACE_LEVEL e = param { Sdl.Max_trace_level (Value.to_int (loc $loc(e)) e) }
  | ADC_BAILOUT e = param { Sdl.Adc_bailout (fl $loc(e) e) }
  | AMBIENT_LIGHT c = color_value { Sdl.Ambient_light (Value.to_rgb (loc $loc(c)) c) }
