(* Light sources, textures, pigments, finishes, interiors. *)
(* (the OCaml header, opening Camlray and Gram, is in grammar_lang.mly) *)

%token LIGHT_SOURCE SPOTLIGHT PARALLEL POINT_AT RADIUS FALLOFF TIGHTNESS
%token FADE_DISTANCE FADE_POWER FADE_COLOR SHADOWLESS
%token TEXTURE PIGMENT FINISH INTERIOR
%token AMBIENT EMISSION DIFFUSE BRILLIANCE PHONG PHONG_SIZE SPECULAR ROUGHNESS METALLIC
%token REFLECTION FRESNEL EXPONENT REFLECTION_EXPONENT CONSERVE_ENERGY IOR

%%

%public object_:
  | LIGHT_SOURCE LBRACE p = param COMMA? c = color_value ms = list(light_mod) RBRACE
      { let l = { Sdl.position = v3 $loc(p) p; color = Value.to_rgb (loc $loc(c)) c;
                  kind = Light.Point; fade_distance = 0.; fade_power = 0.; shadowless = false } in
        let o = { Sdl.loc = loc $loc; shape = Sdl.Light l; xform = Transform.identity;
                  texture = None; interior = None; no_shadow = false; hollow = false } in
        List.fold_left (fun o f -> f o) o ms }

%public light_mod:
  | m = object_mod { m }
  | COLOR? c = color_value_noprefix { fun (o : Sdl.obj) -> match o.shape with
      | Sdl.Light l -> { o with shape = Sdl.Light { l with color = c } } | _ -> o }
  | SPOTLIGHT { light_kind (function _ -> Light.Spot { point_at = Vec3.unit_z; radius = 30.;
                                                       falloff = 45.; tightness = 0. }) }
  | PARALLEL { light_kind (function _ -> Light.Parallel { point_at = Vec3.zero }) }
  | POINT_AT e = param { let p = v3 $loc(e) e in light_kind (function
      | Light.Spot s -> Light.Spot { s with point_at = p }
      | Light.Parallel _ -> Light.Parallel { point_at = p }
      | k -> k) }
  | RADIUS e = param { let r = fl $loc(e) e in light_kind (function
      | Light.Spot s -> Light.Spot { s with radius = r } | k -> k) }
  | FALLOFF e = param { let r = fl $loc(e) e in light_kind (function
      | Light.Spot s -> Light.Spot { s with falloff = r } | k -> k) }
  | TIGHTNESS e = param { let r = fl $loc(e) e in light_kind (function
      | Light.Spot s -> Light.Spot { s with tightness = r } | k -> k) }
  | FADE_DISTANCE e = param { let d = fl $loc(e) e in light_field (fun l -> { l with fade_distance = d }) }
  | FADE_POWER e = param { let d = fl $loc(e) e in light_field (fun l -> { l with fade_power = d }) }
  | SHADOWLESS { light_field (fun l -> { l with shadowless = true }) }

%public color_value_noprefix: k = RGB e = unary { Value.to_rgb (loc $loc) (Value.rgb_kind (loc $loc) k e) }

%public texture_body:
  | t = ioption(TEXTURE_ID) ms = list(texture_mod)
      { let base = match t with Some (top :: _) -> top | _ -> Defaults.texture () in
        List.fold_left (fun l f -> f l) base ms }

%public texture_mod:
  | PIGMENT LBRACE p = pigment_body RBRACE { fun (l : Texture.layer) -> { l with pigment = p } }
  | FINISH LBRACE f = finish_body RBRACE { fun (l : Texture.layer) -> { l with finish = f } }
  | transformation { fun l -> l }

%public pigment_body:
  | p = PIGMENT_ID ms = list(pigment_mod) { ignore ms; p }
  | c = color_value ms = list(pigment_mod) { ignore ms; Pigment.solid (Value.to_color (loc $loc(c)) c) }
  | ms = list(pigment_mod) { ignore ms; (Defaults.texture ()).pigment }

%public pigment_mod:
  | t = transformation { t }

%public finish_body:
  | f = ioption(FINISH_ID) ms = list(finish_item)
      { let base = match f with Some f -> f | None -> (Defaults.texture ()).finish in
        List.fold_left (fun f m -> m f) base ms }

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
  | REFLECTION LBRACE a = color_value b = ioption(preceded(COMMA, color_value)) ms = list(reflection_item) RBRACE
      { let a = Value.to_rgb (loc $loc(a)) a in
        let b = Option.map (fun b -> Value.to_rgb (loc $loc) b) b in
        fun (f : Finish.t) ->
          let r = { f.reflection with rmin = a; rmax = (match b with Some b -> b | None -> a) } in
          let r = List.fold_left (fun r m -> m r) r ms in
          let r = if r.Finish.fresnel && b = None then { r with rmin = Color.black } else r in
          { f with reflection = r } }
  | REFLECTION_EXPONENT e = param
      { let x = fl $loc(e) e in fun (f : Finish.t) -> { f with reflection = { f.reflection with exponent = x } } }
  | CONSERVE_ENERGY b = ioption(param)
      { let on = match b with None -> true | Some v -> Value.to_bool (loc $loc) v in
        fun (f : Finish.t) -> { f with conserve_energy = on } }
  | IOR e = param
      { ignore e; Diag.warning (loc $loc) "ior in finish is obsolete and ignored: use interior { ior ... }";
        fun f -> f }

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
