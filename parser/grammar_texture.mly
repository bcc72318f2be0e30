(* Light sources, textures, pigments, finishes, interiors. *)
(* (the OCaml header, opening Camlray and Gram, is in grammar_lang.mly) *)

%token LIGHT_SOURCE SPOTLIGHT PARALLEL POINT_AT RADIUS FALLOFF TIGHTNESS PROJECTED_THROUGH
%token FADE_DISTANCE FADE_POWER FADE_COLOR SHADOWLESS CAUSTICS
%token TEXTURE PIGMENT FINISH INTERIOR UV_MAPPING
%token AMBIENT EMISSION DIFFUSE BRILLIANCE PHONG PHONG_SIZE SPECULAR ROUGHNESS METALLIC
%token REFLECTION FRESNEL EXPONENT REFLECTION_EXPONENT CONSERVE_ENERGY IOR IRID THICKNESS
%token AREA_LIGHT ADAPTIVE JITTER CIRCULAR ORIENT AREA_ILLUMINATION LOOKS_LIKE SKY_SPHERE NORMAL
%token COLOR_MAP PIGMENT_MAP CHECKER HEXAGON BRICK BRICK_SIZE MORTAR GRADIENT RADIAL ONION PLANAR SPHERICAL BOXED CYLINDRICAL PIGMENT_PATTERN SLOPE_MAP
%token TOROIDAL ORIENTATION DIST_EXP MAJOR_RADIUS
%token WARP REPEAT BLACK_HOLE OFFSET FLIP QUICK_COLOR BUMP_SIZE TILES TILE2 SLOPE ALTITUDE METRIC FORM SOLID
%token CELLS BUMP_MAP USE_INDEX USE_COLOR MATERIAL_MAP USE_ALPHA IMAGE_PATTERN
%token DENSITY_FILE DF3 BOZO SPOTTED GRANITE MARBLE WOOD AGATE AGATE_TURB LEOPARD RIPPLES WAVES WRINKLES BUMPS DENTS
%token TURBULENCE OCTAVES OMEGA LAMBDA FREQUENCY PHASE
%token RAMP_WAVE TRIANGLE_WAVE SINE_WAVE SCALLOP_WAVE CUBIC_WAVE POLY_WAVE
%token IMAGE_MAP PNG ONCE INTERPOLATE MAP_TYPE ALL GAMMA
%token <(float * Camlray.Pigment.t) array> COLOR_MAP_ID
%token <Camlray.Normal.t option> NORMAL_ID
%token CRAND MATERIAL NUMBER_OF_WAVES NOISE_GENERATOR CRACKLE TEXTURE_MAP
%token <Camlray.Texture.t option * Camlray.Interior.t option> MATERIAL_ID
%token <Camlray.Sky.t> SKY_SPHERE_ID
%token TILING
%token SPIRAL1 SPIRAL2 QUILTED CONTROL0 CONTROL1 MANDEL EXTERIOR AVERAGE NORMAL_MAP
%token FACETS COORDS SIZE
%token JULIA MAGNET
%token MEDIA ABSORPTION SCATTERING ECCENTRICITY EXTINCTION DENSITY METHOD INTERVALS SAMPLES
%token CONFIDENCE VARIANCE RATIO AA_THRESHOLD AA_LEVEL MEDIA_INTERACTION MEDIA_ATTENUATION DENSITY_MAP
%token <Camlray.Media.t> MEDIA_ID
%token <Camlray.Pigment.t> DENSITY_ID

%%

%public object_:
  | LIGHT_SOURCE LBRACE o = OBJECT_ID ms = list(light_mod) RBRACE
      { (match o.Sdl.shape with
         | Sdl.Light _ -> ()
         | _ -> Diag.error (loc $loc(o)) "light_source { NAME }: NAME must be a declared light_source");
        List.fold_left (fun o f -> f o) { o with Sdl.loc = loc $loc } ms }
  | LIGHT_SOURCE LBRACE p = param COMMA? c = color_value ms = list(light_mod) RBRACE
      { let l = { Sdl.position = v3 $loc(p) p; color = Value.to_rgb (loc $loc(c)) c;
                  kind = Sdl.Point_light; point_at = Vec3.unit_z; parallel = false; fade_distance = 0.; fade_power = 0.; shadowless = false;
                  media_interaction = true; media_attenuation = false;
                  area = None; looks_like = None; projected_through = None } in
        let o = { Sdl.loc = loc $loc; shape = Sdl.Light l; xform = Transform.identity;
                  texture = None; interior = None; no_shadow = false; hollow = false; flags = 0; inner = None; photon = Photon.none } in
        List.fold_left (fun o f -> f o) o ms }

%public light_mod:
  | m = object_mod { m }
  | COLOR? c = color_value_noprefix { fun (o : Sdl.obj) -> match o.shape with
      | Sdl.Light l -> { o with shape = Sdl.Light { l with color = c } } | _ -> o }
  (* POV-Ray's light types, switched as its parser does: each type
     keyword sets its own radius, falloff and tightness; a cylinder is
     parallel; shadowless makes a point light of any type (so that
     [cylinder shadowless] is a parallel light, [shadowless cylinder] a
     cylinder casting shadows) *)
  | SPOTLIGHT { light_field (fun l -> { l with kind = Sdl.Spot_light { radius = 30.; falloff = 45.; tightness = 0. };
                                               shadowless = false }) }
  | CYLINDER { light_field (fun l -> { l with kind = Sdl.Cylinder_light { radius = 0.75; falloff = 1.; tightness = 0. };
                                              parallel = true; shadowless = false }) }
  | PARALLEL { light_field (fun l -> { l with parallel = true }) }
  | SHADOWLESS { light_field (fun l -> { l with kind = Sdl.Point_light; shadowless = true }) }
  | POINT_AT e = param { let p = v3 $loc(e) e in
      light_param $loc "point_at" ~parallel:true (fun l -> { l with point_at = p }) }
  | RADIUS e = param { let r = fl $loc(e) e in light_param $loc "radius" (fun l -> { l with kind = match l.kind with
      | Sdl.Spot_light s -> Sdl.Spot_light { s with radius = r }
      | Sdl.Cylinder_light s -> Sdl.Cylinder_light { s with radius = r }
      | k -> k }) }
  | FALLOFF e = param { let r = fl $loc(e) e in light_param $loc "falloff" (fun l -> { l with kind = match l.kind with
      | Sdl.Spot_light s -> Sdl.Spot_light { s with falloff = r }
      | Sdl.Cylinder_light s -> Sdl.Cylinder_light { s with falloff = r }
      | k -> k }) }
  | TIGHTNESS e = param { let r = fl $loc(e) e in light_param $loc "tightness" (fun l -> { l with kind = match l.kind with
      | Sdl.Spot_light s -> Sdl.Spot_light { s with tightness = r }
      | Sdl.Cylinder_light s -> Sdl.Cylinder_light { s with tightness = r }
      | k -> k }) }
  | FADE_DISTANCE e = param { let d = fl $loc(e) e in light_field (fun l -> { l with fade_distance = d }) }
  | FADE_POWER e = param { let d = fl $loc(e) e in light_field (fun l -> { l with fade_power = d }) }
  | MEDIA_INTERACTION %prec below_shift { light_field (fun l -> { l with media_interaction = true }) }
  | MEDIA_INTERACTION b = param
      { let on = Value.to_bool (loc $loc) b in light_field (fun l -> { l with media_interaction = on }) }
  | MEDIA_ATTENUATION %prec below_shift { light_field (fun l -> { l with media_attenuation = true }) }
  | MEDIA_ATTENUATION b = param
      { let on = Value.to_bool (loc $loc) b in light_field (fun l -> { l with media_attenuation = on }) }
  | AREA_LIGHT a = param COMMA? b = param COMMA? n1 = param COMMA? n2 = param
      { let a = v3 $loc(a) a and b = v3 $loc(b) b in
        let n1 = Value.to_int (loc $loc(n1)) n1 and n2 = Value.to_int (loc $loc(n2)) n2 in
        if n1 < 1 || n2 < 1 then Diag.error (loc $loc) "area_light needs at least 1 sample along each axis";
        light_field (fun l -> { l with area = Some (Light.area a b n1 n2) }) }
  | ADAPTIVE e = param { let k = Value.to_int (loc $loc(e)) e in area_field (fun a -> { a with adaptive = k }) }
  | JITTER { area_field (fun a -> { a with jitter = true }) }
  | CIRCULAR { area_field (fun a -> { a with circular = true }) }
  | ORIENT { area_field (fun a -> { a with orient = true }) }
  | AREA_ILLUMINATION %prec below_shift { area_field (fun a -> { a with area_illumination = true }) }
  | AREA_ILLUMINATION b = param
      { let on = Value.to_bool (loc $loc) b in area_field (fun a -> { a with area_illumination = on }) }
  | LOOKS_LIKE LBRACE o = object_ RBRACE { light_field (fun l -> { l with looks_like = Some o }) }
  (* projected_through { OBJECT [modifiers] }: the light reaches only what
     sees it through the object, which is never drawn *)
  | PROJECTED_THROUGH LBRACE o = object_ ms = list(object_mod) RBRACE
      { projected_through $loc (List.fold_left (fun o f -> f o) o ms) }
  | PROJECTED_THROUGH LBRACE o = OBJECT_ID ms = list(object_mod) RBRACE
      { projected_through $loc (List.fold_left (fun o f -> f o) { o with Sdl.loc = loc $loc(o) } ms) }
  (* looks_like { Name [modifiers] }: a declared object without object { } *)
  | LOOKS_LIKE LBRACE o = OBJECT_ID ms = list(object_mod) RBRACE
      { let o = List.fold_left (fun o f -> f o) { o with Sdl.loc = loc $loc(o) } ms in
        light_field (fun l -> { l with looks_like = Some o }) }

%public color_value_noprefix: k = RGB e = unary { Value.to_rgb (loc $loc) (Value.rgb_kind (loc $loc) k e) }

(* a texture: its layers, top first ([texture { T_Layered }] keeps every
   layer of T_Layered); pigment, normal and finish change the top layer,
   transformations move every layer *)
%public texture_body:
  | t = ioption(TEXTURE_ID) ms = list(texture_mod)
      { let base = match t with Some (_ :: _ as l) -> l | _ -> [ Defaults.texture () ] in
        List.fold_left (fun l f -> f l) base ms }
  (* the weighted mean of its texture_map's textures, each shaded *)
  | AVERAGE ms = list(tmap_mod)
      { let l = List.fold_left (fun l f -> f l) (Texture.averaged [||]) ms in
        [ Gram.average_texture (loc $loc) l ] }
  (* every pattern of the texture taken at the surface's uv (transformations
     written inside still apply; later ones do not move them, but turn its
     normals: measured) *)
  | UV_MAPPING t = texture_body { Texture.uv_texture t }
  | k = pattern_kind ms = list(tmap_mod)
      { [ List.fold_left (fun l f -> f l) (Texture.patterned (Pattern.make k) [||]) ms ] }
  | FACETS { facets_elsewhere $loc }
  (* material_map { png FILE [once] [map_type 0] TEXTURE... } *)
  | MATERIAL_MAP LBRACE ioption(PNG) f = string_arg os = list(material_map_item) ts = list(block_texture) RBRACE
    ms = list(tmap_mod)
      { let k = Texdesc.material_map (loc $loc(f)) f ~once:(List.mem `Once os) ~count:(List.length ts) in
        let l = Texture.patterned (Pattern.make k) (Array.of_list (List.mapi (fun i t -> (float_of_int i, t)) ts)) in
        [ List.fold_left (fun l f -> f l) l ms ] }
  | OBJECT LBRACE k = pattern_object ts = list(block_texture) RBRACE ms = list(tmap_mod)
      { let l = Texture.patterned (Pattern.make k) (Array.of_list (List.mapi (fun i t -> (float_of_int i, t)) ts)) in
        [ List.fold_left (fun l f -> f l) l ms ] }
  | k = block_kind ts = list(block_texture) ms = list(tmap_mod)
      { let l = Texture.patterned (Pattern.make k) (Array.of_list (List.mapi (fun i t -> (float_of_int i, t)) ts)) in
        [ List.fold_left (fun l f -> f l) l ms ] }

(* POV-Ray's old tiles { texture { A } tile2 texture { B } }: a checker
   of two textures *)
%public texture_body:
  | TILES LBRACE a = block_texture TILE2 b = block_texture RBRACE ms = list(tmap_mod)
      { (* tile2 on the checker's first cells: measured *)
        let l = Texture.patterned (Pattern.make Pattern.Checker) [| (0., b); (1., a) |] in
        [ List.fold_left (fun l f -> f l) l ms ] }

%public block_texture:
  | TEXTURE LBRACE t = texture_body RBRACE COMMA? { t }

(* modifiers of a patterned texture layer *)
%public tmap_mod:
  | t = transformation { Texture.transform_layer t }
  | m = pattern_mod { tmap_pattern m }
  | TEXTURE_MAP LBRACE es = list(texture_map_entry) RBRACE
      { fun (l : Texture.layer) -> match l.tmap with
          | Some m -> { l with tmap = Some { m with entries = Array.of_list es } }
          | None -> l }

%public texture_map_entry:
  | LBRACKET v = param COMMA? t = texture_body RBRACKET { (fl $loc(v) v, t) }
  (* without a value: an average's weight of 1 (other patterns read 1 too) *)
  | LBRACKET t = texture_body RBRACKET { (1., t) }

%public texture_mod:
  | PIGMENT LBRACE p = pigment_edit RBRACE { top_layer (fun l -> { l with pigment = p l.pigment }) }
  | NORMAL LBRACE n = normal_edit RBRACE { top_layer (fun l -> { l with normal = n l.normal }) }
  | FINISH LBRACE f = finish_edit RBRACE { top_layer (fun l -> { l with finish = f l.finish }) }
  | t = transformation { Texture.transform t }

%public object_mod:
  | NORMAL LBRACE n = normal_edit RBRACE
      { fun (o : Sdl.obj) ->
          let uv = o.flags land Sdl.uv_mapping <> 0 in
          with_texture $loc (fun l -> { l with Texture.normal = (let m = n l.normal in
            if uv then Option.map (Normal.uv ~turns:false) m else m) }) o }

%public item:
  | SKY_SPHERE LBRACE k = sky_body RBRACE { Sdl.Sky_sphere k }

%public declare_rhs:
  | k = SKY_SPHERE_ID { Decl.Sky_sphere k }
  | SKY_SPHERE LBRACE k = sky_body RBRACE { Decl.Sky_sphere k }

%public any_value:
  | k = SKY_SPHERE_ID { Decl.Sky_sphere k }
  | SKY_SPHERE LBRACE k = sky_body RBRACE { Decl.Sky_sphere k }

%public global_item:
  | NOISE_GENERATOR e = param { let n = Value.to_int (loc $loc(e)) e in
      if n < 1 || n > 3 then Diag.error (loc $loc(e)) "noise_generator in global_settings is 1, 2 or 3, found %d" n;
      (* from here on the scene's generator, for f_noise3d evaluated
         while parsing (POV-Ray's sets its scene's as it reads it) *)
      Defaults.set_noise_generator n;
      Sdl.Noise_generator n }
  | NUMBER_OF_WAVES e = param { let n = Value.to_int (loc $loc(e)) e in
      (* POV-Ray: "Illegal Value: number_of_waves must be greater than 0.
         Changed to 1." (a warning) *)
      if n < 1 then Diag.warning (loc $loc(e)) (Printf.sprintf "number_of_waves must be greater than 0 (found %d): 1 is used" n);
      Sdl.Number_of_waves (Int.max 1 n) }

%public sky_body:
  | k = ioption(SKY_SPHERE_ID) ms = list(sky_item)
      { List.fold_left (fun k f -> f k) (Option.value ~default:Sky.none k) ms }

%public sky_item:
  | PIGMENT LBRACE p = pigment_body RBRACE { fun (k : Sky.t) -> { k with Sky.pigments = p :: k.pigments } }
  | t = transformation { Sky.transform t }

(* pigment { ... } as it changes the pigment it is written over: POV-Ray
   edits in place, so modifiers alone move or turn the pigment already
   there (texture { T_Stone1 pigment { rotate 90*z } }); a pattern, a
   colour or an identifier replaces it. [pigment_body] is the one written
   over the default pigment. *)
%public pigment_edit:
  | UV_MAPPING e = pigment_edit { fun base -> Pigment.uv (e base) }
  | p = PIGMENT_ID ms = list(pigment_mod) { let p = Texdesc.(pigment (apply ms (of_pigment p))) in fun _ -> p }
  | c = color_value ms = list(pigment_mod)
      { let p = Texdesc.(pigment (apply ms (of_pigment (Pigment.solid (Value.to_color (loc $loc(c)) c))))) in
        fun _ -> p }
  | k = pattern_kind ms = list(pigment_mod) { let p = Texdesc.(pigment (apply ms (of_pattern k))) in fun _ -> p }
  | FACETS { facets_elsewhere $loc }
  (* the weighted mean of its pigment_map's entries (weights 1 when left out) *)
  | AVERAGE ms = list(pigment_mod) { let p = Texdesc.(pigment (apply ms (average ()))) in fun _ -> p }
  | k = block_kind cs = block_cells ms = list(pigment_mod)
      { let p = Texdesc.(pigment (apply ms { (of_pattern k) with cells = cs })) in fun _ -> p }
  | OBJECT LBRACE k = pattern_object cs = block_cells RBRACE ms = list(pigment_mod)
      { let p = Texdesc.(pigment (apply ms { (of_pattern k) with cells = cs })) in fun _ -> p }
  | IMAGE_MAP LBRACE ioption(image_file_kind) f = string_arg file_gamma = ioption(file_gamma) ims = list(image_item) RBRACE
    ms = list(pigment_mod)
      { let p = Texdesc.image_map (loc $loc(f)) ?file_gamma ~gamma_decode:(Defaults.version () >= 3.7) f ims in
        let p = Texdesc.(pigment (apply ms (of_pigment p))) in
        fun _ -> p }
  | ms = list(pigment_mod) { fun base -> Texdesc.(pigment (apply ms (of_pigment base))) }

%public pigment_body: e = pigment_edit { e (Defaults.texture ()).pigment }

%public block_cells:
  | { [] }
  | c = block_cell COMMA? cs = block_cells { c :: cs }

%public block_cell:
  | c = cell_color { Pigment.solid (Value.to_color (loc $loc(c)) c) }
  | PIGMENT LBRACE p = pigment_body RBRACE { p }

(* a colour in a list without separators: no comparisons at the top level *)
%public cell_color:
  | e = param ms = list(channel) { List.fold_left (fun v (l, c, x) -> Value.set_channel l v c x) e ms }
  | COLOR e = param ms = list(channel) { List.fold_left (fun v (l, c, x) -> Value.set_channel l v c x) e ms }
  | COLOR ms = nonempty_list(channel)
      { List.fold_left (fun v (l, c, x) -> Value.set_channel l v c x) (Value.Vector (Array.make 5 0.)) ms }

(* a colour that starts with a keyword (color ..., rgb ...) *)
%public kw_color:
  | COLOR e = param ms = list(channel) { List.fold_left (fun v (l, c, x) -> Value.set_channel l v c x) e ms }
  | COLOR ms = nonempty_list(channel)
      { List.fold_left (fun v (l, c, x) -> Value.set_channel l v c x) (Value.Vector (Array.make 5 0.)) ms }
  | k = RGB e = add ms = list(channel)
      { List.fold_left (fun v (l, c, x) -> Value.set_channel l v c x) (Value.rgb_kind (loc $loc) k e) ms }

(* [gamma G] after an image file's name: the file's values are c^G *)
%public file_gamma:
  | GAMMA g = param
      { let x = fl $loc(g) g in
        if not (x > 0.) then Diag.error (loc $loc(g)) "an image file's gamma must be positive, found %g" x;
        x }

(* the file type before an image's name: PNG, JPEG and PPM are read (by
   their first bytes), others refused by name *)
image_file_kind:
  | PNG { () }
  | k = IMAGE_KIND { readable_kind $loc k }

%public image_item:
  | ONCE { Texdesc.Every (fun (i : Pigment.image) -> { i with once = true }) }
  | INTERPOLATE e = param
      { let n = Value.to_int (loc $loc(e)) e in
        (* POV-Ray's: 2 bilinear, 3 bicubic, 4 normalized distance (0, none,
           camlray reads too) *)
        if not (List.mem n [ 0; 2; 3; 4 ]) then
          Diag.error (loc $loc(e)) "an image_map's interpolate is 2 (bilinear), 3 (bicubic) or 4 (normalized distance), found %d" n;
        Texdesc.Every (fun (i : Pigment.image) -> { i with interpolate = n }) }
  | MAP_TYPE e = param
      { let n = Value.to_int (loc $loc(e)) e in
        (* the ones POV-Ray 3.7.0's parser takes (7, angular, it refuses) *)
        if not (List.mem n [ 0; 1; 2; 5 ]) then
          Diag.error (loc $loc(e)) "an image_map's map_type must be 0 (planar), 1 (spherical), 2 (cylindrical) or 5 (torus), found %d" n;
        Texdesc.Every (fun (i : Pigment.image) -> { i with map_type = n }) }
  | c = CHANNEL ALL e = param
      { let x = fl $loc(e) e in
        let set : Color.rgbft -> Color.rgbft =
          match image_channel $loc(c) c with
          | `Filter -> fun p -> { p with filter = x }
          | `Transmit -> fun p -> { p with transmit = x }
        in
        Texdesc.Every (fun (i : Pigment.image) -> { i with px = Array.map set i.px }) }
  | c = CHANNEL n = param COMMA e = param
      { Texdesc.Entry { loc = loc $loc(n); channel = image_channel $loc(c) c; entry = fl $loc(n) n; amount = fl $loc(e) e } }

(* the object pattern's object: 1 inside, 0 outside (POV-Ray's [object {
   OBJECT cell0 cell1 }], where the object takes only transformations
   before the cells in camlray: wrap it in object { } for more) *)
%public pattern_object:
  | o = OBJECT_ID ts = list(transformation) { Probe.object_pattern (List.fold_left (fun o t -> Sdl.transform_obj t o) o ts) }
  | o = object_ ts = list(transformation) { Probe.object_pattern (List.fold_left (fun o t -> Sdl.transform_obj t o) o ts) }

%public block_kind:
  | CHECKER { Pattern.Checker }
  | HEXAGON { Pattern.Hexagon }
  | BRICK { Pattern.Brick { size = Vec3.make 8. 3. 4.5; mortar = 0.5 } }

%public pattern_kind:
  | GRADIENT e = param { Pattern.gradient (v3 $loc(e) e) }
  | RADIAL { Pattern.Radial }
  | ONION { Pattern.Onion }
  | PLANAR { Pattern.Planar }
  | SPHERICAL { Pattern.Spherical }
  | BOXED { Pattern.Boxed }
  | CYLINDRICAL { Pattern.Cylindrical }
  | WOOD { Pattern.Wood }
  | MARBLE { Pattern.Marble }
  | LEOPARD { Pattern.Leopard }
  | CELLS { Pattern.Cells }
  | BOZO { Pattern.Bozo }
  | DENSITY_FILE DF3 f = string_arg { Texdesc.density_file (loc $loc(f)) f }
  (* image_pattern { [png] FILE [gamma G] [once] [map_type N] [interpolate N]
     [use_color|use_index|use_alpha] } *)
  | IMAGE_PATTERN LBRACE ioption(image_file_kind) f = string_arg g = ioption(file_gamma) items = list(image_pattern_item) RBRACE
      { let alpha = List.fold_left (fun a i -> match i with `Alpha b -> b | _ -> a) false items in
        let interpolate = List.fold_left (fun a i -> match i with `Interpolate n -> n | _ -> a) 0 items in
        let map_type = List.fold_left (fun a i -> match i with `Map_type n -> n | _ -> a) 0 items in
        let once = List.mem `Once items in
        Texdesc.image_pattern (loc $loc(f)) ?file_gamma:g ~alpha ~interpolate ~once ~map_type f }
  | SPOTTED { Pattern.Spotted }
  | BUMPS { Pattern.Bumps }
  | DENTS { Pattern.Dents }
  | GRANITE { Pattern.Granite }
  | AGATE { Pattern.Agate 1. }
  | RIPPLES { Pattern.Ripples }
  | WAVES { Pattern.Waves }
  | WRINKLES { Pattern.Wrinkles }
  | CRACKLE { Pattern.Crackle Pattern.crackle_default }
  (* POV-Ray truncates the number of arms (to a short) *)
  | SPIRAL1 e = param { Pattern.Spiral1 (truncate (fl $loc(e) e)) }
  (* slope { <dir> [, lo, hi] [altitude <dir> [, lo, hi]] }, or slope <dir> *)
  | SLOPE LBRACE v = param r = ioption(slope_range) a = ioption(slope_altitude) RBRACE
      { Gram.slope $loc(v) v r a }
  | SLOPE v = param { Gram.slope $loc(v) v None None }
  | SPIRAL2 e = param { Pattern.Spiral2 (truncate (fl $loc(e) e)) }
  | QUILTED { Pattern.Quilted { c0 = 1.; c1 = 1. } }
  (* tiling N: N truncated, then 1 to 27 (POV-Ray 3.7.0: "Tiling number
     must be between 1 and 27", measured with 0.5, -0.5, 1.5, 27.9, 28) *)
  | TILING e = param
      { let f = fl $loc(e) e in
        if not (f >= 1. && f < 28.) then
          Diag.error (loc $loc(e)) "tiling takes a number from 1 to 27, found %g" f;
        Pattern.Tiling (truncate f) }
  | MANDEL e = param
      { let n = Value.to_int (loc $loc(e)) e in
        if n < 1 then Diag.error (loc $loc(e)) "mandel needs at least 1 iteration";
        Pattern.Mandel (Pattern.mandel n) }
  | MAGNET k = param MANDEL e = param
      { let k = Value.to_int (loc $loc(k)) k and n = Value.to_int (loc $loc(e)) e in
        if k <> 1 && k <> 2 then Diag.error (loc $loc(k)) "magnet is 1 or 2, found %d" k;
        if n < 1 then Diag.error (loc $loc(e)) "magnet needs at least 1 iteration";
        Pattern.Magnet { formula = k; julia = false; cr = 0.; ci = 0.; fractal = Pattern.mandel n } }
  | MAGNET k = param JULIA c = param COMMA? e = param
      { let k = Value.to_int (loc $loc(k)) k and n = Value.to_int (loc $loc(e)) e in
        if k <> 1 && k <> 2 then Diag.error (loc $loc(k)) "magnet is 1 or 2, found %d" k;
        if n < 1 then Diag.error (loc $loc(e)) "magnet needs at least 1 iteration";
        match c with
        | Value.Vector [| cr; ci |] -> Pattern.Magnet { formula = k; julia = true; cr; ci; fractal = Pattern.mandel n }
        | _ -> Diag.error (loc $loc(c)) "magnet julia needs a 2-vector <re, im>, then the iterations" }
  | JULIA c = param COMMA? e = param
      { let n = Value.to_int (loc $loc(e)) e in
        if n < 1 then Diag.error (loc $loc(e)) "julia needs at least 1 iteration";
        match c with
        | Value.Vector [| cr; ci |] -> Pattern.Julia { cr; ci; fractal = Pattern.mandel n }
        | _ -> Diag.error (loc $loc(c)) "julia needs a 2-vector <re, im>, then the iterations" }
  (* function { EXPR } (or a declared function called in it): its value
     at the point, POV-Ray's function pattern *)
  | f = FUNCTION_LIT { Pattern.Function (Fn.pattern (loc $loc(f)) f) }
  | PIGMENT_PATTERN LBRACE p = pigment_body RBRACE { Pattern.Function (Fn.pigment_pattern (loc $loc) p) }

%public declare_rhs:
  | m = COLOR_MAP_ID { Decl.Color_map m }
  | COLOR_MAP LBRACE m = color_map_body RBRACE { Decl.Color_map m }
  | n = NORMAL_ID { Decl.Normal n }
  | NORMAL LBRACE n = normal_body RBRACE { Decl.Normal n }

%public any_value:
  | m = COLOR_MAP_ID { Decl.Color_map m }
  | COLOR_MAP LBRACE m = color_map_body RBRACE { Decl.Color_map m }
  | n = NORMAL_ID { Decl.Normal n }
  | NORMAL LBRACE n = normal_body RBRACE { Decl.Normal n }

%public declare_rhs:
  | m = MATERIAL_ID { Decl.Material m }
  | MATERIAL LBRACE m = material_body RBRACE { Decl.Material m }

%public any_value:
  | m = MATERIAL_ID { Decl.Material m }
  | MATERIAL LBRACE m = material_body RBRACE { Decl.Material m }

%public object_mod:
  | MATERIAL LBRACE m = material_body RBRACE
      { fun (o : Sdl.obj) ->
          let o = match fst m with
            | Some t -> { o with texture = Some (match o.texture with
                | Some l -> Gram.layered (loc $loc) ~above:t ~below:l | None -> t) }
            | None -> o in
          match snd m with Some i -> { o with interior = Some i } | None -> o }

(* material { [M_ID] texture { } ... interior { } transforms }: the last
   texture written is the top layer *)
%public material_body:
  | m = ioption(MATERIAL_ID) ms = list(material_item)
      { List.fold_left (fun m f -> f m) (match m with Some m -> m | None -> (None, None)) ms }

%public material_item:
  | TEXTURE LBRACE t = texture_body RBRACE
      { fun (tex, i) -> (Some (match tex with Some l -> Gram.layered (loc $loc) ~above:t ~below:l | None -> t), i) }
  | INTERIOR LBRACE i = interior_body RBRACE { fun (tex, _) -> (tex, Some i) }
  | t = transformation { fun (tex, i) -> (Option.map (Texture.transform t) tex, i) }

%public default_item:
  (* a normal of modifiers alone perturbs nothing, but the normals
     written after it start from them *)
  | NORMAL LBRACE e = normal_edit RBRACE
      { let n = e None in
        let template =
          match n with Some _ -> n | None -> e (Some (Texdesc.normal (Texdesc.of_pattern Pattern.Bozo)))
        in
        fun () ->
          Defaults.set_normal n;
          Defaults.set_normal_template template }

%public color_map_body:
  | m = COLOR_MAP_ID { m }
  | es = list(map_entry) { Array.of_list (List.concat es) }

%public pigment_mod:
  (* the colour of POV-Ray's low-quality previews (+Q5 and below): camlray
     renders at full quality, so it is read and not used *)
  | QUICK_COLOR c = color_value { ignore c; fun p -> p }
  | t = transformation { Texdesc.transform t }
  | m = pattern_mod { m }
  | COLOR_MAP LBRACE m = color_map_body RBRACE { Texdesc.map (Array.to_list m) }
  | PIGMENT_MAP LBRACE es = list(pigment_map_entry) RBRACE { Texdesc.map es }

%public map_entry:
  | LBRACKET v = param c = color_value RBRACKET
      { [ (fl $loc(v) v, Pigment.solid (Value.to_color (loc $loc(c)) c)) ] }
  | LBRACKET v = param COMMA c = color_value RBRACKET
      { [ (fl $loc(v) v, Pigment.solid (Value.to_color (loc $loc(c)) c)) ] }
  (* the old form [v1, v2 colour1 colour2]: a ramp from v1 to v2 *)
  | LBRACKET v1 = param COMMA v2 = param cs = kw_color_pair RBRACKET { old_entry $loc(v1) v1 $loc(v2) v2 cs }
  | LBRACKET v1 = param v2 = param cs = kw_color_pair RBRACKET { old_entry $loc(v1) v1 $loc(v2) v2 cs }

%public kw_color_pair:
  | c1 = kw_color COMMA? c2 = kw_color
      { (Pigment.solid (Value.to_color (loc $loc(c1)) c1), Pigment.solid (Value.to_color (loc $loc(c2)) c2)) }

%public pigment_map_entry:
  (* without a value: an average's weight of 1 (other patterns read 1 too) *)
  | LBRACKET p = PIGMENT_ID ms = list(pigment_mod) RBRACKET
      { (1., Texdesc.(pigment (apply ms (of_pigment p)))) }
  | LBRACKET k = pattern_kind ms = list(pigment_mod) RBRACKET
      { (1., Texdesc.(pigment (apply ms (of_pattern k)))) }
  | LBRACKET k = block_kind cs = block_cells ms = list(pigment_mod) RBRACKET
      { (1., Texdesc.(pigment (apply ms { (of_pattern k) with cells = cs }))) }
  | LBRACKET v = param COMMA? p = PIGMENT_ID ms = list(pigment_mod) RBRACKET
      { (fl $loc(v) v, Texdesc.(pigment (apply ms (of_pigment p)))) }
  | LBRACKET v = param COMMA? k = pattern_kind ms = list(pigment_mod) RBRACKET
      { (fl $loc(v) v, Texdesc.(pigment (apply ms (of_pattern k)))) }
  | LBRACKET v = param COMMA? k = block_kind cs = block_cells ms = list(pigment_mod) RBRACKET
      { (fl $loc(v) v, Texdesc.(pigment (apply ms { (of_pattern k) with cells = cs }))) }
  | LBRACKET v = param COMMA? c = color_value RBRACKET
      { (fl $loc(v) v, Pigment.solid (Value.to_color (loc $loc(c)) c)) }

%public pattern_mod:
  | TURBULENCE e = param { Texdesc.turbulence (v3 $loc(e) e) }
  (* as POV-Ray's Check_Turb: octaves, omega or lambda before any
     turbulence make one of amount 0 (agate reads its parameters) *)
  | OCTAVES e = param { let n = Value.to_int (loc $loc(e)) e in
      Texdesc.turb_mod (fun tb -> { tb with octaves = max 1 (min 10 n) }) }
  | OMEGA e = param { let x = Floats.single (fl $loc(e) e) in Texdesc.turb_mod (fun tb -> { tb with omega = x }) }
  | LAMBDA e = param { let x = Floats.single (fl $loc(e) e) in Texdesc.turb_mod (fun tb -> { tb with lambda = x }) }
  (* POV-Ray keeps frequency, phase and poly_wave's exponent in single
     precision *)
  | FREQUENCY e = param { let x = Floats.single (fl $loc(e) e) in Texdesc.pattern_mod (fun p -> { p with frequency = x }) }
  | PHASE e = param { let x = Floats.single (fl $loc(e) e) in Texdesc.pattern_mod (fun p -> { p with phase = x }) }
  | RAMP_WAVE { Texdesc.pattern_mod (fun p -> { p with wave = Some Pattern.Ramp }) }
  | TRIANGLE_WAVE { Texdesc.pattern_mod (fun p -> { p with wave = Some Pattern.Triangle }) }
  | SINE_WAVE { Texdesc.pattern_mod (fun p -> { p with wave = Some Pattern.Sine }) }
  | SCALLOP_WAVE { Texdesc.pattern_mod (fun p -> { p with wave = Some Pattern.Scallop }) }
  | CUBIC_WAVE { Texdesc.pattern_mod (fun p -> { p with wave = Some Pattern.Cubic }) }
  | POLY_WAVE e = ioption(param)
      { let x = match e with Some e -> Floats.single (fl $loc(e) e) | None -> 1. in
        Texdesc.pattern_mod (fun p -> { p with wave = Some (Pattern.Poly x) }) }
  (* density_file's interpolation: 0 none, 1 trilinear (2, tricubic,
     read as 1 with a warning) *)
  | INTERPOLATE e = param
      { let n = Value.to_int (loc $loc(e)) e in
        let n =
          if n = 2 then (
            Diag.warning (loc $loc) "density_file's tricubic interpolation (2) is drawn trilinear (1) by camlray";
            1)
          else if n = 0 || n = 1 then n
          else Diag.error (loc $loc(e)) "density_file's interpolate is 0, 1 or 2, found %d" n
        in
        Texdesc.kind_mod (function Pattern.Density_file d -> Pattern.Density_file { d with interpolate = n } | k -> k) }
  | BRICK_SIZE e = param { let v = v3 $loc(e) e in Texdesc.kind_mod (function
      | Pattern.Brick b -> Pattern.Brick { b with size = v } | k -> k) }
  | METRIC e = param { let x = fl $loc(e) e in
      if not (x > 0.) then Diag.error (loc $loc(e)) "a metric must be positive, found %g" x;
      Texdesc.metric x }
  | FORM e = param { let v = v3 $loc(e) e in Texdesc.kind_mod (function
      | Pattern.Crackle c -> Pattern.Crackle { c with form = v } | k -> k) }
  | OFFSET e = param { let x = fl $loc(e) e in Texdesc.kind_mod (function
      | Pattern.Crackle c -> Pattern.Crackle { c with offset = x } | k -> k) }
  | SOLID { Texdesc.kind_mod (function Pattern.Crackle c -> Pattern.Crackle { c with solid = true } | k -> k) }
  | MORTAR e = param { let x = fl $loc(e) e in Texdesc.kind_mod (function
      | Pattern.Brick b -> Pattern.Brick { b with mortar = x } | k -> k) }
  | AGATE_TURB e = param { let x = Floats.single (fl $loc(e) e) in Texdesc.kind_mod (function
      | Pattern.Agate _ -> Pattern.Agate x | k -> k) }
  | WARP LBRACE k = warp_body RBRACE { Texdesc.warp (loc $loc) k }
  | NUMBER_OF_WAVES param { Diag.error (loc $loc) "number_of_waves is a global_settings item (POV-Ray 3.7 takes it nowhere else)" }
  | NOISE_GENERATOR e = param { let n = Value.to_int (loc $loc(e)) e in
      (* 0: the scene's *)
      if n < 0 || n > 3 then Diag.error (loc $loc(e)) "noise_generator is 0, 1, 2 or 3, found %d" n;
      Texdesc.pattern_mod (fun p -> { p with noise_gen = n }) }
  (* quilted's controls are single-precision floats in POV-Ray *)
  | CONTROL0 e = param { let x = Floats.single (fl $loc(e) e) in
      Texdesc.kind_mod (function
        | Pattern.Quilted q -> Pattern.Quilted { q with c0 = x }
        | _ -> Diag.error (loc $loc) "control0 can only be used with quilted") }
  | CONTROL1 e = param { let x = Floats.single (fl $loc(e) e) in
      Texdesc.kind_mod (function
        | Pattern.Quilted q -> Pattern.Quilted { q with c1 = x }
        | _ -> Diag.error (loc $loc) "control1 can only be used with quilted") }
  | EXPONENT e = param
      { let n = Value.to_int (loc $loc(e)) e in
        let n = if n >= 2 && n <= 33 then n else begin
          Diag.warning (loc $loc(e)) "mandel exponents go from 2 to 33: using 2"; 2 end in
        Texdesc.kind_mod (function
          | Pattern.Mandel f -> Pattern.Mandel { f with exponent = n }
          | Pattern.Julia j -> Pattern.Julia { j with fractal = { j.fractal with exponent = n } }
          | _ -> Diag.error (loc $loc) "exponent (in a pattern) can only be used with mandel") }
  | INTERIOR t = param COMMA? e = param
      { let t = Value.to_int (loc $loc(t)) t and x = fl $loc(e) e in
        if t < 0 || t > 6 then Diag.error (loc $loc(t)) "mandel interior types go from 0 to 6";
        Texdesc.kind_mod (function
          | Pattern.Mandel f -> Pattern.Mandel { f with interior = t; ifactor = x }
          | Pattern.Julia j -> Pattern.Julia { j with fractal = { j.fractal with interior = t; ifactor = x } }
          | Pattern.Magnet m -> Pattern.Magnet { m with fractal = { m.fractal with interior = t; ifactor = x } }
          | _ -> Diag.error (loc $loc) "interior (in a pattern) can only be used with mandel") }
  | EXTERIOR t = param COMMA? e = param
      { let t = Value.to_int (loc $loc(t)) t and x = fl $loc(e) e in
        if t < 0 || t > 8 then Diag.error (loc $loc(t)) "mandel exterior types go from 0 to 8";
        Texdesc.kind_mod (function
          | Pattern.Mandel f -> Pattern.Mandel { f with exterior = t; efactor = x }
          | Pattern.Julia j -> Pattern.Julia { j with fractal = { j.fractal with exterior = t; efactor = x } }
          | Pattern.Magnet m -> Pattern.Magnet { m with fractal = { m.fractal with exterior = t; efactor = x } }
          | _ -> Diag.error (loc $loc) "exterior can only be used with mandel") }

(* normal { ... } changes the normal it is written over: modifiers alone
   move the perturbation already there; a pattern or an identifier
   replaces it. [normal_body] is the one written over none. *)
%public normal_edit:
  (* the rest is the normal whose pattern is taken at the surface's uv
     (modifiers written later do not reach it: measured) *)
  | UV_MAPPING e = normal_edit { fun base -> Option.map (Normal.uv ~turns:false) (e base) }
  (* the weighted mean of its normal_map's entries' normals *)
  | AVERAGE ms = list(normal_mod)
      { let p = Texdesc.apply ms (Texdesc.average ()) in
        if p.Texdesc.nmap = None then Diag.error (loc $loc) "an average normal needs a normal_map";
        let n = Some (Texdesc.normal p) in
        fun _ -> n }
  | k = block_kind a = ioption(bump_size) ms = list(normal_mod)
      { let p = Texdesc.of_normal_pattern k in
        let p = match a with Some a -> { p with Texdesc.amount = fl $loc(a) a } | None -> p in
        let n = Some (Texdesc.normal (Texdesc.apply ms p)) in
        fun _ -> n }
  (* checker, hexagon, brick with a list of normals, one a cell *)
  | k = block_kind cs = normal_cells ms = list(normal_mod)
      { let n = Some (Texdesc.normal (Texdesc.apply ms { (Texdesc.of_normal_pattern k) with ncells = cs })) in
        fun _ -> n }
  | n = NORMAL_ID ms = list(normal_mod) { let n = moved ms n in fun _ -> n }
  | k = pattern_kind a = ioption(bump_size) ms = list(normal_mod)
      { let p = Texdesc.of_normal_pattern k in
        let p = match a with Some a -> { p with Texdesc.amount = fl $loc(a) a } | None -> p in
        let n = Some (Texdesc.normal (Texdesc.apply ms p)) in
        fun _ -> n }
  | ms = list(normal_mod) { fun base -> moved ms base }
  (* facets [coords C] [size S] [metric M]: POV-Ray's normal of its own;
     an amount is read and unused, as POV-Ray does *)
  | FACETS ioption(bump_size) ms = list(normal_mod)
      { let p = Texdesc.apply ms (Texdesc.facets ()) in
        if p.Texdesc.nmap <> None then Diag.error (loc $loc) "facets takes no normal_map: it is a normal of its own";
        let n = Some (Texdesc.normal p) in
        fun _ -> n }
  (* bump_map { png FILE [bump_size F] [interpolate N] [use_index|use_color] [map_type 0] [once] } *)
  | BUMP_MAP LBRACE ioption(image_file_kind) f = string_arg items = list(bump_item) RBRACE ms = list(normal_mod)
      { let index = List.fold_left (fun a i -> match i with `Index b -> Some b | _ -> a) None items in
        let interpolate = List.fold_left (fun a i -> match i with `Interpolate n -> n | _ -> a) 0 items in
        let once = List.exists (fun i -> i = `Once) items in
        let p = Texdesc.bump_map (loc $loc(f)) f ~index ~interpolate ~once in
        let p = List.fold_left (fun (p : Texdesc.pat) i -> match i with `Size a -> { p with amount = a } | _ -> p) p items in
        let n = Some (Texdesc.normal (Texdesc.apply ms p)) in
        fun _ -> n }
  | OBJECT LBRACE k = pattern_object cs = normal_cells RBRACE ms = list(normal_mod)
      { let n = Some (Texdesc.normal (Texdesc.apply ms { (Texdesc.of_normal_pattern k) with ncells = cs })) in
        fun _ -> n }
  | OBJECT LBRACE pattern_object RBRACE
      { Diag.error (loc $loc) "the object pattern in a normal needs its two normals (object { OBJECT normal { ... } normal { ... } })" }

%public normal_body: e = normal_edit { e None }

material_map_item:
  | ONCE { `Once }
  | MAP_TYPE e = param
      { let n = Value.to_int (loc $loc(e)) e in
        if n <> 0 then Diag.error (loc $loc(e)) "a material_map's map_type %d is not supported by camlray: only 0 (planar) is" n;
        `Map_type }
  | INTERPOLATE e = param
      { if Value.to_int (loc $loc(e)) e <> 0 then
          Diag.error (loc $loc(e)) "interpolate in a material_map is not supported by camlray";
        `Map_type }

(* POV-Ray 3.7 reads the colours' grey with use_index as with use_color
   (measured on a palette PNG: the same values), the later keyword
   winning *)
image_pattern_item:
  | ONCE { `Once }
  | MAP_TYPE e = param
      { let n = Value.to_int (loc $loc(e)) e in
        if not (List.mem n [ 0; 1; 2; 5 ]) then
          Diag.warning (loc $loc)
            (Printf.sprintf "an image_pattern's map_type %d is drawn planar, as POV-Ray 3.7 draws every map_type but 1 (spherical), 2 (cylindrical) and 5 (torus)" n);
        `Map_type n }
  | INTERPOLATE e = param
      { let n = Value.to_int (loc $loc(e)) e in
        if n <> 0 && n <> 2 && n <> 4 then
          Diag.error (loc $loc(e)) "an image_pattern's interpolate %d is not supported by camlray: 0 (none), 2 (bilinear) and 4 (normalized distance) are" n;
        `Interpolate n }
  | USE_COLOR { `Alpha false }
  | USE_INDEX { `Alpha false }
  | USE_ALPHA { `Alpha true }

bump_item:
  | BUMP_SIZE e = param { `Size (fl $loc(e) e) }
  | INTERPOLATE e = param
      { let n = Value.to_int (loc $loc(e)) e in
        if n <> 0 && n <> 2 && n <> 4 then
          Diag.error (loc $loc(e)) "a bump_map's interpolate %d is not supported by camlray: 0 (none), 2 (bilinear) and 4 (normalized distance) are" n;
        `Interpolate n }
  | USE_INDEX { `Index true }
  | USE_COLOR { `Index false }
  | ONCE { `Once }
  | MAP_TYPE e = param
      { let n = Value.to_int (loc $loc(e)) e in
        if n <> 0 then Diag.error (loc $loc(e)) "a bump_map's map_type %d is not supported by camlray: only 0 (planar) is" n;
        `Map_type }

(* normal { PATTERN [,] BUMP_SIZE ... } *)
bump_size: COMMA? a = param { a }

%public normal_mod:
  | t = transformation { Texdesc.transform t }
  | m = pattern_mod { m }
  | SLOPE_MAP LBRACE es = list(slope_entry) RBRACE { Texdesc.slope_map (loc $loc) es }
  | ACCURACY e = param { Texdesc.accuracy (loc $loc(e)) (fl $loc(e) e) }
  | COORDS e = param { let x = fl $loc(e) e in Texdesc.facets_mod (loc $loc) "coords" (fun f -> { f with Facets.coords = x }) }
  | SIZE e = param { let x = fl $loc(e) e in Texdesc.facets_mod (loc $loc) "size" (fun f -> { f with Facets.size = x }) }
  (* the bump amount, written as a modifier *)
  | BUMP_SIZE e = param { let a = fl $loc(e) e in fun (p : Texdesc.pat) -> { p with amount = a } }
  | NORMAL_MAP LBRACE es = list(normal_map_entry) RBRACE { Texdesc.normal_map (loc $loc) es }

normal_cells:
  | NORMAL LBRACE n = normal_body RBRACE { [ flat n ] }
  | NORMAL LBRACE n = normal_body RBRACE COMMA? cs = normal_cells { flat n :: cs }

(* [value NORMAL_BODY]; without a value, a weight (or value) of 1, as
   POV-Ray reads it (textures/normals/normavg.pov) *)
normal_map_entry:
  | LBRACKET v = param COMMA? n = normal_body RBRACKET { (fl $loc(v) v, flat n) }
  | LBRACKET n = normal_body RBRACKET { (1., flat n) }

(* [value, <height, slope>] *)
slope_entry:
  | LBRACKET v = param COMMA? hs = param RBRACKET
      { match hs with
        | Value.Vector [| h; s |] -> (fl $loc(v) v, h, s)
        | _ -> Diag.error (loc $loc(hs)) "a slope_map entry is [value, <height, slope>]" }

(* finish { ... } changes the finish it is written over (POV-Ray edits in
   place: texture { T finish { reflection 0.1 } } keeps T's highlights);
   an identifier replaces it *)
%public finish_edit:
  | f = ioption(FINISH_ID) ms = list(finish_item)
      { fun base ->
          let base = match f with Some f -> f | None -> base in
          List.fold_left (fun f m -> m f) base ms }

%public finish_body: e = finish_edit { e (Defaults.texture ()).finish }

%public finish_item:
  | AMBIENT c = color_value { let c = Value.to_rgb (loc $loc(c)) c in fun (f : Finish.t) -> { f with ambient = c } }
  | EMISSION c = color_value { let c = Value.to_rgb (loc $loc(c)) c in fun (f : Finish.t) -> { f with emission = c } }
  | DIFFUSE e = param b = ioption(preceded(COMMA, param))
      { let d = fl $loc(e) e in
        let back = match b with Some b -> fl $loc(b) b | None -> 0. in
        fun (f : Finish.t) -> { f with diffuse = d; diffuse_back = back } }
  | BRILLIANCE e = param { let x = fl $loc(e) e in fun (f : Finish.t) -> { f with brilliance = x } }
  | PHONG e = param { let x = fl $loc(e) e in fun (f : Finish.t) -> { f with phong = x } }
  | PHONG_SIZE e = param { let x = fl $loc(e) e in fun (f : Finish.t) -> { f with phong_size = x } }
  | SPECULAR e = param { let x = fl $loc(e) e in fun (f : Finish.t) -> { f with specular = x } }
  | ROUGHNESS e = param
      { let x = fl $loc(e) e in
        if x <= 0. then Diag.error (loc $loc(e)) "roughness must be greater than 0";
        fun (f : Finish.t) -> { f with roughness = x } }
  | METALLIC e = ioption(param)
      { let x = match e with Some e -> fl $loc(e) e | None -> 1. in
        fun (f : Finish.t) -> { f with metallic = x } }
  | REFLECTION c = color_value
      { let c = Value.to_rgb (loc $loc(c)) c in
        fun (f : Finish.t) -> { f with reflection = { f.reflection with rmin = c; rmax = c } } }
  | REFLECTION LBRACE a = color_value b = ioption(reflection_max) ms = list(reflection_item) RBRACE
      { let a = Value.to_rgb (loc $loc(a)) a in
        let b = Option.map (fun b -> Value.to_rgb (loc $loc) b) b in
        fun (f : Finish.t) ->
          let r = { f.reflection with rmin = a; rmax = (match b with Some b -> b | None -> a) } in
          let r = List.fold_left (fun r m -> m r) r ms in
          let r = if r.Finish.fresnel && b = None then { r with rmin = Color.black } else r in
          { f with reflection = r } }
  | REFLECTION_EXPONENT e = param
      { let x = fl $loc(e) e in fun (f : Finish.t) -> { f with reflection = { f.reflection with exponent = x } } }
  (* irid { amount [thickness t] [turbulence u] } *)
  | IRID LBRACE a = param ms = list(irid_item) RBRACE
      { let a = fl $loc(a) a in
        fun (f : Finish.t) -> List.fold_left (fun f m -> m f) { f with irid = a } ms }
  | CONSERVE_ENERGY b = ioption(param)
      { let on = match b with None -> true | Some v -> Value.to_bool (loc $loc) v in
        fun (f : Finish.t) -> { f with conserve_energy = on } }
  | IOR e = param
      { ignore e; Diag.warning (loc $loc) "ior in finish is obsolete and ignored: use interior { ior ... }";
        fun f -> f }

%public finish_item:
  | CRAND e = param { ignore e; fun f -> f }  (* random grain: not reproducible, ignored *)

(* reflection { MIN, MAX }: POV-Ray lets the comma go, as between a
   vector's components (reflection { 0.0 1.0 fresnel on }) *)
reflection_max:
  | COMMA c = color_value { c }
  | f = FLOAT { Value.Float f }
  | f = FLOAT_ID { Value.Float f }
  | v = VECTOR_ID { Value.Vector v }
  | k = RGB e = unary { Value.rgb_kind (loc $loc) k e }

%public reflection_item:
  | FRESNEL b = ioption(param)
      { let on = match b with None -> true | Some v -> Value.to_bool (loc $loc) v in
        fun (r : Finish.reflection) -> { r with fresnel = on } }
  | FALLOFF e = param { let x = fl $loc(e) e in fun (r : Finish.reflection) -> { r with falloff = x } }
  | EXPONENT e = param { let x = fl $loc(e) e in fun (r : Finish.reflection) -> { r with exponent = x } }
  | METALLIC e = ioption(param)
      { let x = match e with Some e -> fl $loc(e) e | None -> 1. in
        fun (r : Finish.reflection) -> { r with rmetallic = x } }

%public interior_body:
  | i = ioption(INTERIOR_ID) ms = list(interior_item)
      { List.fold_left (fun i m -> m i) (match i with Some i -> i | None -> Interior.default) ms }

%public interior_item:
  | IOR e = param { let x = fl $loc(e) e in fun (i : Interior.t) -> { i with ior = x } }
  | FADE_DISTANCE e = param { let x = fl $loc(e) e in fun (i : Interior.t) -> { i with fade_distance = x } }
  | FADE_POWER e = param { let x = fl $loc(e) e in fun (i : Interior.t) -> { i with fade_power = x } }
  | FADE_COLOR c = color_value
      { let c = Value.to_rgb (loc $loc(c)) c in fun (i : Interior.t) -> { i with fade_color = c } }
  (* POV-Ray keeps 45 times the value written *)
  | CAUSTICS e = param { let x = 45. *. fl $loc(e) e in fun (i : Interior.t) -> { i with caustics = x } }
  (* several media add up, in source order *)
  | MEDIA LBRACE m = media_body RBRACE { fun (i : Interior.t) -> { i with media = i.media @ [ m ] } }

(* media { ... }: POV-Ray's participating media, sampled as POV-Ray 3.7
   does (see Camlray.Volume) *)
%public media_body:
  | m = ioption(MEDIA_ID) ms = list(media_item)
      { List.fold_left (fun m f -> f m) (Option.value ~default:Media.default m) ms }

(* density { [D] ... }: a density is read as a pigment whose colour is
   the density per channel (white: 1) *)
%public density_body:
  | d = DENSITY_ID ms = list(pigment_mod) { Texdesc.(pigment (apply ms (of_pigment d))) }
  | e = pigment_edit { e (Pigment.solid (Color.rgbft 1. 1. 1. 0. 0.)) }

%public declare_rhs:
  | m = MEDIA_ID { Decl.Media m }
  | MEDIA LBRACE m = media_body RBRACE { Decl.Media m }
  | d = DENSITY_ID { Decl.Density d }
  | DENSITY LBRACE d = density_body RBRACE { Decl.Density d }

%public any_value:
  | m = MEDIA_ID { Decl.Media m }
  | MEDIA LBRACE m = media_body RBRACE { Decl.Media m }
  | d = DENSITY_ID { Decl.Density d }
  | DENSITY LBRACE d = density_body RBRACE { Decl.Density d }

(* density_map { [v DENSITY] ... }: a pigment_map of densities (camlray
   reads it wherever a pigment_map may stand) *)
%public pigment_mod:
  | DENSITY_MAP LBRACE es = list(density_map_entry) RBRACE { Texdesc.map es }

density_map_entry:
  | e = pigment_map_entry { e }
  | LBRACKET v = param COMMA? d = DENSITY_ID ms = list(pigment_mod) RBRACKET
      { (fl $loc(v) v, Texdesc.(pigment (apply ms (of_pigment d)))) }

media_item:
  | EMISSION c = color_value { let c = Value.to_rgb (loc $loc(c)) c in fun (m : Media.t) -> { m with emission = c } }
  | ABSORPTION c = color_value { let c = Value.to_rgb (loc $loc(c)) c in fun (m : Media.t) -> { m with absorption = c } }
  | SCATTERING LBRACE k = param COMMA c = color_value ss = list(scattering_item) RBRACE
      { let k = Value.to_int (loc $loc(k)) k in
        if k < 1 || k > 5 then Diag.error (loc $loc(k)) "scattering types go from 1 to 5";
        let s = List.fold_left (fun s f -> f s) (Media.scattering k (Value.to_rgb (loc $loc(c)) c)) ss in
        fun (m : Media.t) -> { m with scattering = Some s } }
  (* several densities multiply *)
  | DENSITY LBRACE d = density_body RBRACE { fun (m : Media.t) -> { m with density = m.density @ [ d ] } }
  | METHOD e = param
      { let k = Value.to_int (loc $loc(e)) e in
        if k = 1 then Diag.error (loc $loc) "media method 1 (random sampling) is not supported by camlray: use method 2 or 3";
        if k < 1 || k > 3 then Diag.error (loc $loc(e)) "media methods go from 1 to 3";
        fun (m : Media.t) -> { m with meth = k } }
  | INTERVALS e = param
      { let k = Value.to_int (loc $loc(e)) e in
        if k < 1 then Diag.error (loc $loc(e)) "media needs at least 1 interval";
        fun (m : Media.t) -> { m with intervals = k } }
  | SAMPLES a = param b = preceded(COMMA, param)?
      { let a = Value.to_int (loc $loc(a)) a in
        let b = match b with Some b -> Value.to_int (loc $loc(b)) b | None -> a in
        if a < 1 then Diag.error (loc $loc(a)) "media needs at least 1 sample";
        if b < a then Diag.error (loc $loc(b)) "media's maximum samples must be at least its minimum";
        fun (m : Media.t) -> { m with samples = a; samples_max = b } }
  | CONFIDENCE e = param { let x = fl $loc(e) e in fun (m : Media.t) -> { m with confidence = x } }
  | VARIANCE e = param { let x = fl $loc(e) e in fun (m : Media.t) -> { m with variance = x } }
  | RATIO e = param { let x = fl $loc(e) e in fun (m : Media.t) -> { m with ratio = x } }
  | JITTER e = param { let x = fl $loc(e) e in fun (m : Media.t) -> { m with jitter = x } }
  | AA_THRESHOLD e = param { let x = fl $loc(e) e in fun (m : Media.t) -> { m with aa_threshold = x } }
  | AA_LEVEL e = param
      { let k = Value.to_int (loc $loc(e)) e in
        if k < 1 then Diag.error (loc $loc(e)) "aa_level in media must be at least 1";
        fun (m : Media.t) -> { m with aa_level = k } }
  | t = transformation { Media.transform t }
  (* photons: collect [on|off] *)
  | w = PHOTON_WORD b = ioption(param)
      { if w <> "collect" then Diag.error (loc $loc(w)) "%s is a photons word: media take collect" w;
        let on = match b with Some b -> Value.to_bool (loc $loc(b)) b | None -> true in
        fun (m : Media.t) -> { m with collect = on } }

scattering_item:
  | ECCENTRICITY e = param { let x = fl $loc(e) e in fun (s : Media.scattering) -> { s with eccentricity = x } }
  | EXTINCTION e = param { let x = fl $loc(e) e in fun (s : Media.scattering) -> { s with extinction = x } }

(* arrays of declared maps, normals and materials:
   #declare A = array[2] { M_Glass, M_Glass2 } *)
%public array_elem:
  | d = texture_decl_id COMMA { (d, false) }
  | d = texture_decl_id RBRACE { (d, true) }

texture_decl_id:
  | m = COLOR_MAP_ID { Decl.Color_map m }
  | n = NORMAL_ID { Decl.Normal n }
  | m = MATERIAL_ID { Decl.Material m }

irid_item:
  | THICKNESS e = param { let x = fl $loc(e) e in fun (f : Finish.t) -> { f with irid_thickness = x } }
  | TURBULENCE e = param
      { let x = match e with Value.Vector v when Array.length v > 0 -> v.(0) | e -> fl $loc(e) e in
        fun (f : Finish.t) -> { f with irid_turb = x } }

(* warp { repeat V [offset V] [flip V] }, warp { black_hole C, R ... },
   warp { turbulence V [octaves N] [omega F] [lambda F] } *)
warp_body:
  | REPEAT e = param ms = list(repeat_item)
      { let v = v3 $loc(e) e in
        let axis, width =
          match List.filter (fun (_, c) -> c <> 0.) [ (0, v.x); (1, v.y); (2, v.z) ] with
          | [ a ] -> a
          | _ -> Diag.error (loc $loc(e)) "repeat needs a vector along one axis (x*2, -y, ...)"
        in
        let offset, flip =
          List.fold_left (fun (o, f) m -> match m with
            | `Offset v -> (v, f)
            | `Flip (v : Vec3.t) ->
                (o, Vec3.make (if v.x <> 0. then -1. else 1.) (if v.y <> 0. then -1. else 1.) (if v.z <> 0. then -1. else 1.)))
            (Vec3.zero, Vec3.one) ms
        in
        Pattern.Repeat { axis; width; offset; flip } }
  | BLACK_HOLE c = param COMMA r = param ms = list(hole_item)
      { let radius = fl $loc(r) r in
        if not (radius > 0.) then Diag.error (loc $loc(r)) "a black hole's radius must be positive, found %g" radius;
        List.fold_left (fun k m -> m k)
          (Pattern.Black_hole { center = v3 $loc(c) c; radius; strength = 1.; falloff = 2.; inverse = false;
                                repeat = Vec3.zero; jitter = Vec3.zero })
          ms }
  | TURBULENCE e = param ms = list(warp_turb_item)
      { Pattern.Turbulence (List.fold_left (fun t m -> m t) (Pattern.default_turbulence (v3 $loc(e) e)) ms) }
  | PLANAR { Pattern.Planar_map { orient = Vec3.unit_z; offset = 0. } }
  | PLANAR v = param COMMA d = param
      { Pattern.Planar_map { orient = orientation $loc(v) v; offset = fl $loc(d) d } }
  | SPHERICAL ms = list(mapping_item)
      { let orient, dist_exp = mapping ms in Pattern.Spherical_map { orient; dist_exp } }
  | CYLINDRICAL ms = list(mapping_item)
      { let orient, dist_exp = mapping ms in Pattern.Cylindrical_map { orient; dist_exp } }
  | TOROIDAL ms = list(toroidal_item)
      { let orient, dist_exp = mapping ms in
        let major = List.fold_left (fun r m -> match m with `Major x -> x | _ -> r) 1. ms in
        Pattern.Toroidal_map { orient; dist_exp; major } }

(* the mapping warps' options *)
mapping_item:
  | ORIENTATION e = param { `Orient (orientation $loc(e) e) }
  | DIST_EXP e = param { `Dist_exp (fl $loc(e) e) }

toroidal_item:
  | m = mapping_item { m }
  | MAJOR_RADIUS e = param { `Major (fl $loc(e) e) }

repeat_item:
  | OFFSET e = param { `Offset (v3 $loc(e) e) }
  | FLIP e = param { `Flip (v3 $loc(e) e) }

hole_item:
  | STRENGTH e = param { let x = fl $loc(e) e in function Pattern.Black_hole h -> Pattern.Black_hole { h with strength = x } | k -> k }
  | FALLOFF e = param { let x = fl $loc(e) e in function Pattern.Black_hole h -> Pattern.Black_hole { h with falloff = x } | k -> k }
  | INVERSE { function Pattern.Black_hole h -> Pattern.Black_hole { h with inverse = not h.inverse } | k -> k }
  | REPEAT e = param { let v = v3 $loc(e) e in let l = loc $loc in
      function Pattern.Black_hole h -> Texdesc.check_black_hole l (Pattern.Black_hole { h with repeat = v }) | k -> k }
  | TURBULENCE e = param { let v = v3 $loc(e) e in let l = loc $loc in
      function Pattern.Black_hole h -> Texdesc.check_black_hole l (Pattern.Black_hole { h with jitter = v }) | k -> k }

warp_turb_item:
  (* POV-Ray keeps octaves within 1 to 10 *)
  | OCTAVES e = param
      { let n = max 1 (min 10 (Value.to_int (loc $loc(e)) e)) in
        fun (t : Pattern.turbulence) -> { t with octaves = n } }
  | OMEGA e = param { let x = Floats.single (fl $loc(e) e) in fun (t : Pattern.turbulence) -> { t with omega = x } }
  | LAMBDA e = param { let x = Floats.single (fl $loc(e) e) in fun (t : Pattern.turbulence) -> { t with lambda = x } }

slope_range: COMMA lo = param COMMA hi = param { (fl $loc(lo) lo, fl $loc(hi) hi) }

slope_altitude: ALTITUDE v = param r = ioption(slope_range) { ($loc(v), v, r) }
