(* The grammar of camlray's scene language (a subset of POV-Ray 3.7's).
   Directives never reach this grammar: the token supplier (Supplier)
   evaluates them and hands over identifiers already typed by what they
   are bound to (FLOAT_ID, OBJECT_ID, ...). Semantic actions evaluate as
   they go, as POV-Ray does; errors in them raise Diag.Error. *)
%{
open Camlray
let loc (s, e) = Loc.make s e
let v3 l v = Value.to_vec3 (loc l) v
let fl l v = Value.to_float (loc l) v
let with_texture f (o : Sdl.obj) =
  let layers = match o.texture with Some t -> t | None -> [ Defaults.texture () ] in
  match layers with
  | top :: rest -> { o with texture = Some (f top :: rest) }
  | [] -> o
let light_kind f (o : Sdl.obj) = match o.shape with
  | Sdl.Light l -> { o with shape = Sdl.Light { l with kind = f l.kind } } | _ -> o
let light_field f (o : Sdl.obj) = match o.shape with
  | Sdl.Light l -> { o with shape = Sdl.Light (f l) } | _ -> o
let nonzero_scale l (v : Vec3.t) =
  let fix c = if c = 0. then (Diag.warning (loc l) "zero scale component replaced by 1"; 1.) else c in
  Vec3.make (fix v.x) (fix v.y) (fix v.z)
%}

%token <float> FLOAT
%token <string> STRING
%token <float array> VECTOR
%token <float> FLOAT_ID
%token <float array> VECTOR_ID
%token <string> STRING_ID
%token <Sdl.obj> OBJECT_ID
%token <Camlray.Pigment.t> PIGMENT_ID
%token <Camlray.Finish.t> FINISH_ID
%token <Camlray.Texture.t> TEXTURE_ID
%token <Camlray.Interior.t> INTERIOR_ID
%token <Camlray.Transform.t> TRANSFORM_ID
%token <Sdl.camera_item list> CAMERA_ID
%token <string> UNDEFINED_ID
%token <string> FUNC
%token <string> MEMBER
%token <string> RGB
%token <string> CHANNEL
%token LBRACE RBRACE LPAREN RPAREN LBRACKET RBRACKET
%token LT GT LE GE EQ NE PLUS MINUS STAR SLASH COMMA SEMI QUESTION COLON AND OR BANG
%token EOF
%token CAMERA PERSPECTIVE ORTHOGRAPHIC LOCATION LOOK_AT ANGLE RIGHT UP DIRECTION SKY
%token APERTURE FOCAL_POINT BLUR_SAMPLES
%token LIGHT_SOURCE SPOTLIGHT PARALLEL POINT_AT RADIUS FALLOFF TIGHTNESS
%token FADE_DISTANCE FADE_POWER FADE_COLOR SHADOWLESS
%token COLOR SPHERE PLANE OBJECT
%token BACKGROUND GLOBAL_SETTINGS ASSUMED_GAMMA MAX_TRACE_LEVEL ADC_BAILOUT AMBIENT_LIGHT
%token TEXTURE PIGMENT FINISH INTERIOR
%token AMBIENT EMISSION DIFFUSE BRILLIANCE PHONG PHONG_SIZE SPECULAR ROUGHNESS METALLIC
%token REFLECTION FRESNEL EXPONENT REFLECTION_EXPONENT CONSERVE_ENERGY IOR
%token SCALE ROTATE TRANSLATE MATRIX TRANSFORM INVERSE NO_SHADOW HOLLOW

(* Greedy parsing where POV-Ray is greedy: a parameter extends over a
   following '+'/'-', a member access binds to the nearest value. *)
%nonassoc below_shift
%nonassoc PLUS MINUS MEMBER RGB

%start <Sdl.item list> scene
%start <Decl.t> declare_rhs
%start <Value.t> paren_expr
%start <Value.t> expr_then_semi
%start <Value.t> expr_then_comma
%start <Value.t> expr_then_rparen
%start <Value.t> expr_then_rbracket
%start <Decl.t * bool> macro_arg
%start <Decl.t * bool> array_elem
%start <string> string_arg
%start <unit> default_body

%%

(* ---------- entry points ---------- *)

scene: items = list(item) EOF { items }

item:
  | o = object_ { Defaults.mark_item (); Sdl.Object o }
  | CAMERA LBRACE c = camera_body RBRACE { Defaults.mark_item (); Sdl.Camera (loc $loc, c) }
  | BACKGROUND LBRACE c = color_value RBRACE
      { Sdl.Background (Value.to_color (loc $loc(c)) c) }
  | GLOBAL_SETTINGS LBRACE g = list(global_item) RBRACE { Sdl.Global_settings (loc $loc, g) }

declare_rhs:
  | v = color_value SEMI { Decl.Value v }
  | o = OBJECT_ID { Decl.Object o }
  | p = PIGMENT_ID { Decl.Pigment p }
  | f = FINISH_ID { Decl.Finish f }
  | t = TEXTURE_ID { Decl.Texture t }
  | i = INTERIOR_ID { Decl.Interior i }
  | t = TRANSFORM_ID { Decl.Transform t }
  | c = CAMERA_ID { Decl.Camera c }
  | o = object_ { Decl.Object o }
  | PIGMENT LBRACE p = pigment_body RBRACE { Decl.Pigment p }
  | FINISH LBRACE f = finish_body RBRACE { Decl.Finish f }
  | TEXTURE LBRACE t = texture_body RBRACE { Decl.Texture [ t ] }
  | INTERIOR LBRACE i = interior_body RBRACE { Decl.Interior i }
  | TRANSFORM LBRACE t = transform_body RBRACE { Decl.Transform t }
  | CAMERA LBRACE c = camera_body RBRACE { Decl.Camera c }

paren_expr: LPAREN e = expr RPAREN { e }
expr_then_semi: e = expr SEMI { e }
expr_then_comma: e = expr COMMA { e }
expr_then_rparen: e = expr RPAREN { e }
expr_then_rbracket: e = expr RBRACKET { e }

macro_arg:
  | d = any_value COMMA { (d, false) }
  | d = any_value RPAREN { (d, true) }

array_elem:
  | d = any_value COMMA { (d, false) }
  | d = any_value RBRACE { (d, true) }

string_arg:
  | s = STRING { s }
  | s = STRING_ID { s }
  | f = FUNC LPAREN args = separated_list(COMMA, expr) RPAREN
      { Value.to_string_value (loc $loc) (Value.call (loc $loc) f args) }

default_body:
  | LBRACE ds = list(default_item) RBRACE { List.iter (fun f -> f ()) ds }

default_item:
  | FINISH LBRACE f = finish_body RBRACE { fun () -> Defaults.set_finish f }
  | PIGMENT LBRACE p = pigment_body RBRACE { fun () -> Defaults.set_pigment p }
  | TEXTURE LBRACE t = texture_body RBRACE
      { fun () -> Defaults.set_pigment t.Texture.pigment; Defaults.set_finish t.Texture.finish }

any_value:
  | o = OBJECT_ID { Decl.Object o }
  | p = PIGMENT_ID { Decl.Pigment p }
  | f = FINISH_ID { Decl.Finish f }
  | t = TEXTURE_ID { Decl.Texture t }
  | i = INTERIOR_ID { Decl.Interior i }
  | t = TRANSFORM_ID { Decl.Transform t }
  | c = CAMERA_ID { Decl.Camera c }
  | v = color_value { Decl.Value v }
  | o = object_ { Decl.Object o }
  | PIGMENT LBRACE p = pigment_body RBRACE { Decl.Pigment p }
  | FINISH LBRACE f = finish_body RBRACE { Decl.Finish f }
  | TEXTURE LBRACE t = texture_body RBRACE { Decl.Texture [ t ] }
  | INTERIOR LBRACE i = interior_body RBRACE { Decl.Interior i }
  | TRANSFORM LBRACE t = transform_body RBRACE { Decl.Transform t }

(* ---------- expressions ---------- *)

expr:
  | c = logic QUESTION a = expr COLON b = expr
      { if Value.to_bool (loc $loc(c)) c then a else b }
  | e = logic { e }

logic:
  | a = logic AND b = rel { Value.binop (loc $loc) "&" a b }
  | a = logic OR b = rel { Value.binop (loc $loc) "|" a b }
  | e = rel { e }

rel:
  | a = rel LT b = add { Value.binop (loc $loc) "<" a b }
  | a = rel LE b = add { Value.binop (loc $loc) "<=" a b }
  | a = rel GT b = add { Value.binop (loc $loc) ">" a b }
  | a = rel GE b = add { Value.binop (loc $loc) ">=" a b }
  | a = rel EQ b = add { Value.binop (loc $loc) "=" a b }
  | a = rel NE b = add { Value.binop (loc $loc) "!=" a b }
  | e = add { e }

(* Object and keyword parameters: no comparisons at the top level, so that
   the next '<' starts a vector (POV-Ray's commas are often optional). *)
add:
  | a = add PLUS b = mul { Value.binop (loc $loc) "+" a b }
  | a = add MINUS b = mul { Value.binop (loc $loc) "-" a b }
  | e = mul { e }

mul:
  | a = mul STAR b = unary { Value.binop (loc $loc) "*" a b }
  | a = mul SLASH b = unary { Value.binop (loc $loc) "/" a b }
  | e = unary { e }

unary:
  | MINUS e = unary { Value.neg (loc $loc) e }
  | PLUS e = unary { e }
  | BANG e = unary { Value.not_ (loc $loc) e }
  | e = postfix %prec below_shift { e }

postfix:
  | e = primary { e }
  | e = postfix m = MEMBER { Value.dot_member (loc $loc) e m }

primary:
  | f = FLOAT { Value.Float f }
  | f = FLOAT_ID { Value.Float f }
  | v = VECTOR { Value.Vector v }
  | v = VECTOR_ID { Value.Vector v }
  | s = STRING { Value.String s }
  | s = STRING_ID { Value.String s }
  | LPAREN e = expr RPAREN { e }
  | LT cs = separated_nonempty_list(COMMA, add) GT
      { let n = List.length cs in
        if n < 2 || n > 5 then
          Diag.error (loc $loc) "a vector has 2 to 5 components, this one has %d" n;
        Value.Vector (Array.of_list (List.map (fun c -> match c with
          | Value.Float f -> f
          | v -> Diag.error (loc $loc) "vector components must be floats, found %s" (Value.type_name v)) cs)) }
  | f = FUNC LPAREN args = separated_list(COMMA, expr) RPAREN { Value.call (loc $loc) f args }
  | k = RGB e = unary { Value.rgb_kind (loc $loc) k e }

param: e = add %prec below_shift { e }

(* a colour: optional 'color', a value, then channel settings *)
color_value:
  | e = expr ms = list(channel) { List.fold_left (fun v (l, c, x) -> Value.set_channel l v c x) e ms }
  | COLOR e = expr ms = list(channel) { List.fold_left (fun v (l, c, x) -> Value.set_channel l v c x) e ms }
  | COLOR ms = nonempty_list(channel)
      { List.fold_left (fun v (l, c, x) -> Value.set_channel l v c x) (Value.Vector (Array.make 5 0.)) ms }

channel: c = CHANNEL e = param { (loc $loc, c, fl $loc(e) e) }

(* ---------- transforms ---------- *)

transformation:
  | SCALE e = param { Transform.scale (nonzero_scale $loc(e) (v3 $loc(e) e)) }
  | ROTATE e = param { Transform.rotate (v3 $loc(e) e) }
  | TRANSLATE e = param { Transform.translate (v3 $loc(e) e) }
  | MATRIX e = param
      { match e with
        | Value.Vector a when Array.length a = 12 -> (
            match Transform.of_pov_matrix a with
            | Some t -> t
            | None -> Diag.error (loc $loc) "this matrix is singular")
        | _ -> Diag.error (loc $loc) "matrix needs 12 numbers <a,b,c, d,e,f, g,h,i, j,k,l>" }
  | TRANSFORM t = TRANSFORM_ID { t }
  | TRANSFORM LBRACE t = transform_body RBRACE { t }

transform_body:
  | ts = list(transform_item) { List.fold_left (fun acc f -> f acc) Transform.identity ts }

transform_item:
  | t = transformation { fun acc -> Transform.then_ acc t }
  | t = TRANSFORM_ID { fun acc -> Transform.then_ acc t }
  | INVERSE { fun acc -> Transform.inverse acc }

(* ---------- objects ---------- *)

object_:
  | SPHERE LBRACE c = param COMMA? r = param ms = list(object_mod) RBRACE
      { let o = { Sdl.loc = loc $loc; shape = Sdl.Sphere (v3 $loc(c) c, fl $loc(r) r);
                  xform = Transform.identity; texture = None; interior = None;
                  no_shadow = false; hollow = false } in
        List.fold_left (fun o f -> f o) o ms }
  | PLANE LBRACE n = param COMMA? d = param ms = list(object_mod) RBRACE
      { let nv = v3 $loc(n) n in
        if Vec3.length nv = 0. then Diag.error (loc $loc(n)) "a plane's normal cannot be zero";
        let o = { Sdl.loc = loc $loc; shape = Sdl.Plane (nv, fl $loc(d) d);
                  xform = Transform.identity; texture = None; interior = None;
                  no_shadow = false; hollow = false } in
        List.fold_left (fun o f -> f o) o ms }
  | OBJECT LBRACE o = OBJECT_ID ms = list(object_mod) RBRACE
      { List.fold_left (fun o f -> f o) { o with Sdl.loc = loc $loc } ms }
  | LIGHT_SOURCE LBRACE p = param COMMA? c = color_value ms = list(light_mod) RBRACE
      { let l = { Sdl.position = v3 $loc(p) p; color = Value.to_rgb (loc $loc(c)) c;
                  kind = Light.Point; fade_distance = 0.; fade_power = 0.; shadowless = false } in
        let o = { Sdl.loc = loc $loc; shape = Sdl.Light l; xform = Transform.identity;
                  texture = None; interior = None; no_shadow = false; hollow = false } in
        List.fold_left (fun o f -> f o) o ms }

object_mod:
  | t = transformation { Sdl.transform_obj t }
  | TEXTURE LBRACE t = texture_body RBRACE
      { fun (o : Sdl.obj) -> { o with texture = Some (match o.texture with
          | Some layers -> t :: layers | None -> [ t ]) } }
  | PIGMENT LBRACE p = pigment_body RBRACE
      { with_texture (fun l -> { l with Texture.pigment = p }) }
  | FINISH LBRACE f = finish_body RBRACE
      { with_texture (fun l -> { l with Texture.finish = f }) }
  | INTERIOR LBRACE i = interior_body RBRACE { fun (o : Sdl.obj) -> { o with interior = Some i } }
  | NO_SHADOW { fun (o : Sdl.obj) -> { o with no_shadow = true } }
  | HOLLOW %prec below_shift { fun (o : Sdl.obj) -> { o with hollow = true } }
  | HOLLOW b = param { let h = Value.to_bool (loc $loc) b in fun (o : Sdl.obj) -> { o with hollow = h } }

light_mod:
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

color_value_noprefix: k = RGB e = unary { Value.to_rgb (loc $loc) (Value.rgb_kind (loc $loc) k e) }

(* ---------- textures ---------- *)

texture_body:
  | t = ioption(TEXTURE_ID) ms = list(texture_mod)
      { let base = match t with Some (top :: _) -> top | _ -> Defaults.texture () in
        List.fold_left (fun l f -> f l) base ms }

texture_mod:
  | PIGMENT LBRACE p = pigment_body RBRACE { fun (l : Texture.layer) -> { l with pigment = p } }
  | FINISH LBRACE f = finish_body RBRACE { fun (l : Texture.layer) -> { l with finish = f } }
  | transformation { fun l -> l }

pigment_body:
  | p = PIGMENT_ID ms = list(pigment_mod) { ignore ms; p }
  | c = color_value ms = list(pigment_mod) { ignore ms; Pigment.solid (Value.to_color (loc $loc(c)) c) }
  | ms = list(pigment_mod) { ignore ms; (Defaults.texture ()).pigment }

pigment_mod:
  | t = transformation { t }

finish_body:
  | f = ioption(FINISH_ID) ms = list(finish_item)
      { let base = match f with Some f -> f | None -> (Defaults.texture ()).finish in
        List.fold_left (fun f m -> m f) base ms }

finish_item:
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

reflection_item:
  | FRESNEL b = ioption(param)
      { let on = match b with None -> true | Some v -> Value.to_bool (loc $loc) v in
        fun (r : Finish.reflection) -> { r with fresnel = on } }
  | FALLOFF e = param { let x = fl $loc(e) e in fun (r : Finish.reflection) -> { r with falloff = x } }
  | EXPONENT e = param { let x = fl $loc(e) e in fun (r : Finish.reflection) -> { r with exponent = x } }
  | METALLIC e = ioption(param)
      { let x = match e with Some e -> fl $loc(e) e | None -> 1. in
        fun (r : Finish.reflection) -> { r with rmetallic = x } }

interior_body:
  | i = ioption(INTERIOR_ID) ms = list(interior_item)
      { List.fold_left (fun i m -> m i) (match i with Some i -> i | None -> Interior.default) ms }

interior_item:
  | IOR e = param { let x = fl $loc(e) e in fun (i : Interior.t) -> { i with ior = x } }
  | FADE_DISTANCE e = param { let x = fl $loc(e) e in fun (i : Interior.t) -> { i with fade_distance = x } }
  | FADE_POWER e = param { let x = fl $loc(e) e in fun (i : Interior.t) -> { i with fade_power = x } }
  | FADE_COLOR c = color_value
      { let c = Value.to_rgb (loc $loc(c)) c in fun (i : Interior.t) -> { i with fade_color = c } }

(* ---------- camera and settings ---------- *)

camera_body:
  | c = ioption(CAMERA_ID) items = list(camera_item)
      { (match c with Some c -> c | None -> []) @ items }

camera_item:
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

global_item:
  | ASSUMED_GAMMA e = param { Sdl.Assumed_gamma (fl $loc(e) e) }
  | MAX_TRACE_LEVEL e = param { Sdl.Max_trace_level (Value.to_int (loc $loc(e)) e) }
  | ADC_BAILOUT e = param { Sdl.Adc_bailout (fl $loc(e) e) }
  | AMBIENT_LIGHT c = color_value { Sdl.Ambient_light (Value.to_rgb (loc $loc(c)) c) }
