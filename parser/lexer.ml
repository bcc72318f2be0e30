open Parser

type raw = Tok of Parser.token | Ident of string | Directive of string | Eof
type token = { raw : raw; loc : Loc.t }

(* Keywords by grammar file; each list is owned by the grammar file of
   the same name, so that they grow independently. *)

(* grammar_lang.mly *)
let lang_keywords =
  [
    ("color", COLOR); ("colour", COLOR); ("scale", SCALE); ("rotate", ROTATE);
    ("translate", TRANSLATE); ("matrix", MATRIX); ("transform", TRANSFORM);
    ("inverse", INVERSE);
    ("x", VECTOR [| 1.; 0.; 0. |]); ("y", VECTOR [| 0.; 1.; 0. |]);
    ("z", VECTOR [| 0.; 0.; 1. |]); ("t", VECTOR [| 0.; 0.; 0.; 1. |]);
    ("u", VECTOR [| 1.; 0. |]); ("v", VECTOR [| 0.; 1. |]);
    ("pi", FLOAT Float.pi); ("true", FLOAT 1.); ("yes", FLOAT 1.); ("on", FLOAT 1.);
    ("false", FLOAT 0.); ("no", FLOAT 0.); ("off", FLOAT 0.);
  ]
  @ List.map (fun k -> (k, RGB k)) [ "rgb"; "rgbf"; "rgbt"; "rgbft"; "srgb"; "srgbf"; "srgbt"; "srgbft" ]
  @ List.map (fun k -> (k, CHANNEL k)) [ "red"; "green"; "blue"; "filter"; "transmit" ]
  @ List.map (fun k -> (k, FUNC k)) Value.functions

(* grammar_scene.mly *)
let scene_keywords =
  [
    ("camera", CAMERA); ("perspective", PERSPECTIVE); ("orthographic", ORTHOGRAPHIC);
    ("fisheye", FISHEYE); ("omnimax", OMNIMAX); ("ultra_wide_angle", ULTRA_WIDE_ANGLE);
    ("panoramic", PANORAMIC);
    ("location", LOCATION); ("look_at", LOOK_AT); ("angle", ANGLE); ("right", RIGHT);
    ("up", UP); ("direction", DIRECTION); ("sky", SKY); ("aperture", APERTURE);
    ("focal_point", FOCAL_POINT); ("blur_samples", BLUR_SAMPLES); ("mesh_camera", MESH_CAMERA);
    ("background", BACKGROUND); ("global_settings", GLOBAL_SETTINGS);
    ("assumed_gamma", ASSUMED_GAMMA); ("max_trace_level", MAX_TRACE_LEVEL);
    ("adc_bailout", ADC_BAILOUT); ("ambient_light", AMBIENT_LIGHT);
    ("irid_wavelength", IRID_WAVELENGTH); ("fog", FOG); ("fog_type", FOG_TYPE);
    ("fog_offset", FOG_OFFSET); ("fog_alt", FOG_ALT); ("turb_depth", TURB_DEPTH); ("distance", DISTANCE);
    ("rainbow", RAINBOW); ("width", WIDTH); ("arc_angle", ARC_ANGLE); ("falloff_angle", FALLOFF_ANGLE);
    ("radiosity", RADIOSITY); ("save_file", RAD_FILE "save_file"); ("load_file", RAD_FILE "load_file");
    ("photons", PHOTONS);
  ]
  @ List.map (fun k -> (k, PHOTON_WORD k))
      [ "spacing"; "gather"; "autostop"; "expand_thresholds"; "target"; "collect"; "pass_through"; "split_union";
        "refraction" ]
  @ List.map (fun k -> (k, RAD_WORD k))
      [ "count"; "recursion_limit"; "brightness"; "error_bound"; "pretrace_start"; "pretrace_end";
        "nearest_count"; "low_error_factor"; "gray_threshold"; "minimum_reuse"; "maximum_reuse";
        "always_sample"; "max_sample"; "subsurface"; "importance" ]

(* grammar_objects.mly *)
let object_keywords =
  [
    ("sphere", SPHERE); ("plane", PLANE); ("object", OBJECT); ("no_shadow", NO_SHADOW);
    ("no_image", NO_IMAGE); ("no_reflection", NO_REFLECTION); ("no_radiosity", NO_RADIOSITY); ("double_illuminate", DOUBLE_ILLUMINATE);
    ("hollow", HOLLOW); ("box", BOX); ("cylinder", CYLINDER); ("cone", CONE); ("torus", TORUS);
    ("disc", DISC); ("triangle", TRIANGLE); ("smooth_triangle", SMOOTH_TRIANGLE); ("mesh", MESH);
    ("mesh2", MESH2); ("open", OPEN); ("sturm", STURM); ("vertex_vectors", VERTEX_VECTORS);
    ("normal_vectors", NORMAL_VECTORS); ("uv_vectors", UV_VECTORS); ("face_indices", FACE_INDICES);
    ("normal_indices", NORMAL_INDICES); ("uv_indices", UV_INDICES); ("uv_mapping", UV_MAPPING); ("texture_list", TEXTURE_LIST);
    ("inside_vector", INSIDE_VECTOR); ("union", UNION); ("intersection", INTERSECTION);
    ("difference", DIFFERENCE); ("merge", MERGE); ("clipped_by", CLIPPED_BY);
    ("bounded_by", BOUNDED_BY); ("quartic", QUARTIC); ("cubic", CUBIC); ("poly", POLY);
    ("quadric", QUADRIC); ("text", TEXT); ("ttf", TTF); ("internal", INTERNAL); ("blob", BLOB);
    ("threshold", THRESHOLD); ("strength", STRENGTH); ("component", COMPONENT); ("hierarchy", HIERARCHY);
    ("prism", PRISM); ("lathe", LATHE); ("superellipsoid", SUPERELLIPSOID); ("polygon", POLYGON);
    ("bicubic_patch", BICUBIC_PATCH); ("sor", SOR); ("julia_fractal", JULIA_FRACTAL); ("quaternion", QUATERNION); ("hypercomplex", HYPERCOMPLEX); ("cube", CUBE);
    ("max_iteration", MAX_ITERATION); ("precision", PRECISION); ("slice", SLICE); ("interior_texture", INTERIOR_TEXTURE); ("type", TYPE); ("flatness", FLATNESS); ("u_steps", U_STEPS); ("v_steps", V_STEPS);
    ("height_field", HEIGHT_FIELD); ("water_level", WATER_LEVEL); ("smooth", SMOOTH);
    ("gif", IMAGE_KIND "gif"); ("tga", IMAGE_KIND "tga"); ("iff", IMAGE_KIND "iff"); ("ppm", IMAGE_KIND "ppm");
    ("pgm", IMAGE_KIND "pgm"); ("sys", IMAGE_KIND "sys"); ("jpeg", IMAGE_KIND "jpeg"); ("tiff", IMAGE_KIND "tiff");
    ("bmp", IMAGE_KIND "bmp"); ("exr", IMAGE_KIND "exr"); ("hdr", IMAGE_KIND "hdr"); ("pot", IMAGE_KIND "pot");
    ("isosurface", ISOSURFACE); ("contained_by", CONTAINED_BY);
    ("accuracy", ACCURACY); ("max_gradient", MAX_GRADIENT); ("evaluate", EVALUATE); ("max_trace", MAX_TRACE);
    ("all_intersections", ALL_INTERSECTIONS); ("light_group", LIGHT_GROUP); ("global_lights", GLOBAL_LIGHTS);
  ]

(* grammar_texture.mly *)
let texture_keywords =
  [
    ("light_source", LIGHT_SOURCE); ("spotlight", SPOTLIGHT); ("parallel", PARALLEL);
    ("projected_through", PROJECTED_THROUGH);
    ("point_at", POINT_AT); ("radius", RADIUS); ("falloff", FALLOFF);
    ("tightness", TIGHTNESS); ("fade_distance", FADE_DISTANCE); ("fade_power", FADE_POWER);
    ("fade_color", FADE_COLOR); ("fade_colour", FADE_COLOR); ("shadowless", SHADOWLESS);
    ("texture", TEXTURE); ("pigment", PIGMENT); ("finish", FINISH); ("interior", INTERIOR);
    ("ambient", AMBIENT); ("emission", EMISSION); ("diffuse", DIFFUSE);
    ("brilliance", BRILLIANCE); ("phong", PHONG); ("phong_size", PHONG_SIZE);
    ("specular", SPECULAR); ("roughness", ROUGHNESS); ("metallic", METALLIC);
    ("reflection", REFLECTION); ("fresnel", FRESNEL); ("exponent", EXPONENT);
    ("reflection_exponent", REFLECTION_EXPONENT); ("conserve_energy", CONSERVE_ENERGY);
    ("irid", IRID); ("thickness", THICKNESS);
    ("ior", IOR); ("area_light", AREA_LIGHT); ("adaptive", ADAPTIVE); ("jitter", JITTER);
    ("circular", CIRCULAR); ("orient", ORIENT); ("area_illumination", AREA_ILLUMINATION);
    ("looks_like", LOOKS_LIKE); ("sky_sphere", SKY_SPHERE); ("normal", NORMAL);
    ("color_map", COLOR_MAP); ("colour_map", COLOR_MAP); ("pigment_map", PIGMENT_MAP);
    ("checker", CHECKER); ("hexagon", HEXAGON); ("brick", BRICK); ("brick_size", BRICK_SIZE);
    ("mortar", MORTAR); ("gradient", GRADIENT); ("radial", RADIAL); ("onion", ONION); ("planar", PLANAR); ("spherical", SPHERICAL); ("boxed", BOXED); ("pigment_pattern", PIGMENT_PATTERN); ("slope_map", SLOPE_MAP); ("warp", WARP); ("repeat", REPEAT); ("black_hole", BLACK_HOLE);
    ("offset", OFFSET); ("flip", FLIP); ("quick_color", QUICK_COLOR); ("julia", JULIA); ("bump_size", BUMP_SIZE); ("tiles", TILES); ("tile2", TILE2); ("slope", SLOPE); ("altitude", ALTITUDE); ("metric", METRIC); ("form", FORM); ("solid", SOLID); ("magnet", MAGNET); ("quick_colour", QUICK_COLOR); ("cylindrical", CYLINDRICAL);
    ("toroidal", TOROIDAL); ("orientation", ORIENTATION); ("dist_exp", DIST_EXP); ("major_radius", MAJOR_RADIUS);
    ("bozo", BOZO); ("density_file", DENSITY_FILE); ("df3", DF3); ("spotted", SPOTTED); ("granite", GRANITE); ("marble", MARBLE);
    ("wood", WOOD); ("agate", AGATE); ("agate_turb", AGATE_TURB); ("leopard", LEOPARD); ("cells", CELLS); ("bump_map", BUMP_MAP); ("material_map", MATERIAL_MAP); ("use_index", USE_INDEX); ("use_color", USE_COLOR); ("use_colour", USE_COLOR); ("use_alpha", USE_ALPHA); ("image_pattern", IMAGE_PATTERN);
    ("ripples", RIPPLES); ("waves", WAVES); ("wrinkles", WRINKLES); ("bumps", BUMPS);
    ("dents", DENTS); ("turbulence", TURBULENCE); ("octaves", OCTAVES); ("omega", OMEGA);
    ("lambda", LAMBDA); ("frequency", FREQUENCY); ("phase", PHASE); ("ramp_wave", RAMP_WAVE);
    ("triangle_wave", TRIANGLE_WAVE); ("sine_wave", SINE_WAVE); ("scallop_wave", SCALLOP_WAVE);
    ("cubic_wave", CUBIC_WAVE); ("poly_wave", POLY_WAVE); ("image_map", IMAGE_MAP);
    ("png", PNG); ("once", ONCE); ("interpolate", INTERPOLATE); ("gamma", GAMMA); ("map_type", MAP_TYPE);
    ("all", ALL); ("crand", CRAND);
    ("material", MATERIAL); ("number_of_waves", NUMBER_OF_WAVES);
    ("noise_generator", NOISE_GENERATOR); ("crackle", CRACKLE);
    ("texture_map", TEXTURE_MAP); ("spiral1", SPIRAL1); ("spiral2", SPIRAL2); ("quilted", QUILTED); ("tiling", TILING);
    ("facets", FACETS); ("coords", COORDS); ("size", SIZE);
    ("control0", CONTROL0); ("control1", CONTROL1); ("mandel", MANDEL); ("exterior", EXTERIOR);
    ("average", AVERAGE); ("normal_map", NORMAL_MAP); ("caustics", CAUSTICS);
    ("media", MEDIA); ("absorption", ABSORPTION); ("scattering", SCATTERING);
    ("eccentricity", ECCENTRICITY); ("extinction", EXTINCTION); ("density", DENSITY);
    ("method", METHOD); ("intervals", INTERVALS); ("samples", SAMPLES); ("confidence", CONFIDENCE);
    ("variance", VARIANCE); ("ratio", RATIO); ("aa_threshold", AA_THRESHOLD); ("aa_level", AA_LEVEL);
    ("media_interaction", MEDIA_INTERACTION); ("media_attenuation", MEDIA_ATTENUATION);
    ("density_map", DENSITY_MAP);
  ]

(* Keywords to their tokens, each token made once and shared by every
   occurrence (a large scene has millions) *)
module Words = Hashtbl.Make (String)

let keywords : raw Words.t =
  let t = Words.create 256 in
  List.iter
    (fun (k, v) ->
      if Words.mem t k then invalid_arg ("Lexer: keyword listed twice: " ^ k);
      Words.replace t k (Tok v))
    (lang_keywords @ scene_keywords @ object_keywords @ texture_keywords);
  t

(* POV-Ray 3.7's reserved words (its keyword list, as in Vim's pov.vim); the
   ones camlray's lexer knows are keywords before this list is consulted. *)
let pov_words =
  "aa_level aa_threshold abs absorption accuracy acos acosh adaptive adc_bailout agate \
   agate_turb all all_intersections alpha altitude always_sample ambient ambient_light angle \
   aoi aperture arc_angle area_illumination area_light array asc ascii asin asinh assumed_gamma \
   atan atan2 atanh atmosphere autostop average b_spline background bezier_spline bicubic_patch \
   bitwise_and bitwise_or bitwise_xor black_hole blob blur_samples bokeh bounded_by box boxed \
   bozo brick brick_size brightness brilliance bump_map bump_size bumps camera caustics ceil \
   cells charset checker chr circular clipped_by clock clock_delta clock_on collect color \
   color_map colour colour_map component composite concat cone confidence conic_sweep \
   conserve_energy contained_by control0 control1 coords cos cosh count crackle crand cube \
   cubic cubic_spline cubic_wave cutaway_textures cylinder cylindrical datetime defined degrees \
   density density_file density_map dents deprecated df3 difference diffuse dimension_size \
   dimensions direction disc dispersion dispersion_samples dist_exp distance distance_maximum \
   dither div double_illuminate eccentricity emission error_bound evaluate exp expand \
   expand_thresholds exponent exr exterior extinction face_indices facets fade_color \
   fade_colour fade_distance fade_power falloff falloff_angle false file_exists filter \
   final_clock final_frame finish fisheye flatness flip floor focal_point fog fog_alt \
   fog_offset fog_type form frame_number frequency fresnel function gamma gather gif \
   global_lights global_settings gradient granite gray_threshold h_angle hdr height_field \
   hexagon hf_gray_16 hierarchy hollow hypercomplex iff image_height image_map image_pattern \
   image_width importance initial_clock initial_frame input_file_name inside inside_vector int \
   interior interior_texture internal interpolate intersection intervals inverse ior irid \
   irid_wavelength isosurface jitter jpeg julia julia_fractal lambda lathe leopard light_group \
   light_source linear_spline linear_sweep ln load_file location log look_at looks_like \
   low_error_factor magnet major_radius mandel map_type marble material material_map matrix max \
   max_extent max_gradient max_intersections max_iteration max_sample max_trace max_trace_level \
   maximum_reuse media media_attenuation media_interaction merge mesh mesh2 mesh_camera \
   metallic method metric min min_extent minimum_reuse mm_per_unit mod mortar natural_spline \
   nearest_count no no_bump_scale no_image no_radiosity no_reflection no_shadow noise_generator \
   normal normal_indices normal_map normal_vectors now number_of_waves object octaves off \
   offset omega omnimax on once onion open orient orientation orthographic ovus panoramic \
   parallel parametric pass_through pattern pavement perspective pgm phase phong phong_size \
   photons pi pigment pigment_map pigment_pattern planar plane png point_at poly poly_wave \
   polygon polynomial pot pov pow ppm precision precompute premultiplied pretrace_end \
   pretrace_start prism prod projected_through pwr quadratic_spline quadric quartic quaternion \
   quick_color quick_colour quilted radial radians radiosity radius rainbow ramp_wave rand \
   range range_divider ratio read reciprocal recursion_limit reflection reflection_exponent \
   refraction render repeat rgb rgbf rgbft rgbt right ripples rotate roughness samples \
   save_file scale scallop_wave scattering seed select sgi shadowless sin sine_wave sinh \
   sint16be sint16le sint32be sint32le sint8 size sky sky_sphere slice slope slope_map smooth \
   smooth_triangle solid sor spacing specular sphere sphere_sweep spherical spiral1 spiral2 \
   spline split_union spotlight spotted sqr sqrt square srgb srgbf srgbft srgbt str strcmp \
   strength strlen strlwr strupr sturm substr subsurface sum superellipsoid sys t tan tanh \
   target text texture texture_list texture_map tga thickness threshold tiff tightness tile2 \
   tiles tiling tolerance toroidal torus trace transform translate transmit triangle \
   triangle_wave triangular true ttf turb_depth turbulence type u_steps uint16be uint16le uint8 \
   ultra_wide_angle union up use_alpha use_color use_colour use_index utf8 uv_indices \
   uv_mapping uv_vectors v_angle v_steps val variance vaxis_rotate vcross vdot version \
   vertex_vectors vlength vnormalize vrotate vstr vturbulence warning warp water_level waves \
   width wood wrinkles write x y yes z \
   albedo xyz statistics number_of_tiles steps bmp translucency number_of_sides dtag \
   anisotropy append"

(* keyed by strings as strings: a #declare asks it for each name (the
   polymorphic table hashed in C and compared with compare_val) *)
let reserved =
  let t = Words.create 512 in
  List.iter
    (fun w -> if w <> "" then Words.replace t w ())
    (String.split_on_char ' ' pov_words);
  t

let keyword_names () = Words.fold (fun k _ acc -> k :: acc) keywords [] |> List.sort compare

(* the keyword of each keyword token (the table walked whole per
   question cost a parse 8% of its instructions: function bodies written
   back as text, messages made for alternatives tried); where two
   keywords make one token, the one the walk found last, as the walk
   did *)
let names_of_tokens =
  let t = Hashtbl.create 512 in
  Words.iter (fun k v -> Hashtbl.replace t v k) keywords;
  t

let keyword_of raw = Hashtbl.find_opt names_of_tokens raw

let pov_reserved w = Words.mem reserved w || Words.mem keywords w

let describe = function
  | Eof -> "end of file"
  | Ident s -> "identifier " ^ s
  | Directive d -> "#" ^ d
  | Tok t -> (
      match t with
      | LBRACE -> "'{'" | RBRACE -> "'}'" | LPAREN -> "'('" | RPAREN -> "')'"
      | LBRACKET -> "'['" | RBRACKET -> "']'" | LT -> "'<'" | GT -> "'>'"
      | LE -> "'<='" | GE -> "'>='" | EQ -> "'='" | NE -> "'!='" | PLUS -> "'+'"
      | MINUS -> "'-'" | STAR -> "'*'" | SLASH -> "'/'" | COMMA -> "','"
      | SEMI -> "';'" | QUESTION -> "'?'" | COLON -> "':'" | AND -> "'&'" | OR -> "'|'"
      | BANG -> "'!'" | EOF -> "end of file"
      | FUNCTION_ID _ | FUNCTION_LIT _ -> "a function"
      | FLOAT_ID _ -> "a float identifier" | VECTOR_ID _ -> "a vector identifier"
      | STRING_ID _ -> "a string identifier" | OBJECT_ID _ -> "an object identifier"
      | PIGMENT_ID _ -> "a pigment identifier" | FINISH_ID _ -> "a finish identifier"
      | TEXTURE_ID _ -> "a texture identifier" | INTERIOR_ID _ -> "an interior identifier"
      | TRANSFORM_ID _ -> "a transform identifier" | CAMERA_ID _ -> "a camera identifier"
      | MEDIA_ID _ -> "a media identifier" | DENSITY_ID _ -> "a density identifier"
      | UNDEFINED_ID s -> "undefined identifier " ^ s
      | FLOAT f -> Printf.sprintf "number %g" f
      | STRING s -> Printf.sprintf "string %S" s
      | MEMBER m -> "." ^ m
      | FUNC f -> "function " ^ f
      | RGB k -> "keyword " ^ k
      | CHANNEL k -> "keyword " ^ k
      | _ -> ( match keyword_of (Tok t) with Some k -> "keyword " ^ k | None -> "a declared identifier"))

exception Lex_error of string

(* An error that belongs to the token's opening (a string's quote, a
   comment's slash-star), located there. *)
exception Unclosed of string * Lexing.position * Lexing.position

let rec comment depth buf =
  match%sedlex buf with
  | "*/" -> if depth > 1 then comment (depth - 1) buf
  | "/*" -> comment (depth + 1) buf
  | eof -> raise (Lex_error "unterminated comment /* ... */")
  | any -> comment depth buf
  | _ -> assert false

let string_body buf =
  let b = Buffer.create 16 in
  let rec go () =
    match%sedlex buf with
    | '"' -> Buffer.contents b
    | "\\\"" -> Buffer.add_char b '"'; go ()
    | "\\\\" -> Buffer.add_char b '\\'; go ()
    | "\\n" -> Buffer.add_char b '\n'; go ()
    | "\\t" -> Buffer.add_char b '\t'; go ()
    | "\\r" -> Buffer.add_char b '\r'; go ()
    | "\\a" -> Buffer.add_char b '\007'; go ()
    | "\\b" -> Buffer.add_char b '\b'; go ()
    | "\\f" -> Buffer.add_char b '\012'; go ()
    | "\\v" -> Buffer.add_char b '\011'; go ()
    | "\\'" -> Buffer.add_char b '\''; go ()
    | '\\', any -> Buffer.add_string b (Sedlexing.Utf8.lexeme buf); go ()
    | '\n' | eof -> raise (Lex_error "unterminated string")
    | any -> Buffer.add_string b (Sedlexing.Utf8.lexeme buf); go ()
    | _ -> assert false
  in
  go ()

let digit = [%sedlex.regexp? '0' .. '9']
let exponent = [%sedlex.regexp? ('e' | 'E'), Opt ('+' | '-'), Plus digit]
let number =
  [%sedlex.regexp? (Plus digit, Opt ('.', Star digit), Opt exponent)
                  | ('.', Plus digit, Opt exponent)]
let ident = [%sedlex.regexp? ('a' .. 'z' | 'A' .. 'Z' | '_'), Star ('a' .. 'z' | 'A' .. 'Z' | '0' .. '9' | '_')]

(* Powers of ten that are exact doubles *)
let exact_tens = Array.init 23 (fun k -> float_of_string ("1e" ^ string_of_int k))

(* The value of the [number] just matched, as [float_of_string] gives it.
   Most numbers in a scene have at most 15 significant digits and a small
   power of ten: their digits, an integer below 2^53, times or divided by
   an exact power of ten up to 10^22 is one correctly rounded operation,
   so the result is the nearest double, as strtod's (Clinger's fast path);
   others go through the lexeme's text. *)
let number_value buf =
  let n = Sedlexing.lexeme_length buf in
  let c i = Uchar.to_int (Sedlexing.lexeme_char buf i) in
  let m = ref 0 and sig_digits = ref 0 and scale = ref 0 and i = ref 0 in
  let digits ~after_point =
    while !i < n && c !i >= 48 && c !i <= 57 do
      let d = c !i - 48 in
      if !sig_digits > 0 || d > 0 then begin
        m := (!m * 10) + d;
        incr sig_digits
      end;
      if after_point then decr scale;
      incr i
    done
  in
  digits ~after_point:false;
  if !i < n && c !i = 46 (* . *) then begin
    incr i;
    digits ~after_point:true
  end;
  let exp_ok =
    if !i < n then begin
      (* e or E, a sign, digits *)
      incr i;
      let neg = !i < n && c !i = 45 in
      if !i < n && (c !i = 45 || c !i = 43) then incr i;
      let e = ref 0 and k = ref 0 in
      while !i < n do
        e := (!e * 10) + (c !i - 48);
        incr k;
        incr i
      done;
      scale := !scale + if neg then - !e else !e;
      !k <= 4
    end
    else true
  in
  if exp_ok && !sig_digits <= 15 then
    if !m = 0 then 0.
    else if !scale >= 0 && !scale <= 22 then float_of_int !m *. Array.unsafe_get exact_tens !scale
    else if !scale < 0 && !scale >= -22 then float_of_int !m /. Array.unsafe_get exact_tens (- !scale)
    else float_of_string (Sedlexing.Utf8.lexeme buf)
  else float_of_string (Sedlexing.Utf8.lexeme buf)

let rec next buf : raw =
  match%sedlex buf with
  | Plus (' ' | '\t' | '\r' | '\n' | '\012' | 0xfeff) -> next buf
  | "//", Star (Compl '\n') -> next buf
  | "/*" ->
      let s, e = Sedlexing.lexing_positions buf in
      (try comment 1 buf with Lex_error m -> raise (Unclosed (m, s, e)));
      next buf
  | number -> Tok (FLOAT (number_value buf))
  | '"' ->
      let s, e = Sedlexing.lexing_positions buf in
      Tok (STRING (try string_body buf with Lex_error m -> raise (Unclosed (m, s, e))))
  | '.', ident ->
      let s = Sedlexing.Utf8.lexeme buf in
      Tok (MEMBER (String.sub s 1 (String.length s - 1)))
  | '#', Star (' ' | '\t'), ident ->
      let s = Sedlexing.Utf8.lexeme buf in
      let i = ref 1 in
      while s.[!i] = ' ' || s.[!i] = '\t' do incr i done;
      Directive (String.sub s !i (String.length s - !i))
  | ident -> (
      let s = Sedlexing.Utf8.lexeme buf in
      match Words.find_opt keywords s with Some t -> t | None -> Ident s)
  | '#' -> next buf (* a '#' not followed by a word: POV-Ray ignores it *)
  | '{' -> Tok LBRACE | '}' -> Tok RBRACE | '(' -> Tok LPAREN | ')' -> Tok RPAREN
  | '[' -> Tok LBRACKET | ']' -> Tok RBRACKET
  | "<=" -> Tok LE | ">=" -> Tok GE | "!=" -> Tok NE
  | '<' -> Tok LT | '>' -> Tok GT | '=' -> Tok EQ
  | '+' -> Tok PLUS | '-' -> Tok MINUS | '*' -> Tok STAR | '/' -> Tok SLASH
  | ',' -> Tok COMMA | ';' -> Tok SEMI | '?' -> Tok QUESTION | ':' -> Tok COLON
  | '&' -> Tok AND | '|' -> Tok OR | '!' -> Tok BANG
  | eof -> Eof
  | any -> raise (Lex_error (Printf.sprintf "unexpected character %S" (Sedlexing.Utf8.lexeme buf)))
  | _ -> raise (Lex_error "invalid UTF-8 input")

(* Sedlexing.Utf8.from_string, decoding straight into sedlex's buffer
   (the library's goes through a generator and allocates at every
   character: 8% of checking 10^6 spheres). As there, a malformed
   sequence ends the characters handed over and raises at the next
   refill; positions count bytes as well as characters. *)
let lexbuf_of_utf8 text =
  let at = ref 0 and malformed = ref false in
  let refill buf pos len =
    if !malformed then raise Sedlexing.MalFormed;
    let n = String.length text and i = ref 0 in
    while !i < len && !at < n do
      let c = Char.code (String.unsafe_get text !at) in
      if c < 0x80 then begin
        (* ASCII, nearly every byte of a scene: no decoding *)
        Array.unsafe_set buf (pos + !i) (Uchar.unsafe_of_int c);
        incr at;
        incr i
      end
      else
      let d = String.get_utf_8_uchar text !at in
      if not (Uchar.utf_decode_is_valid d) then begin
        if !i = 0 then raise Sedlexing.MalFormed;
        malformed := true;
        at := n (* stop here *)
      end
      else begin
        Array.unsafe_set buf (pos + !i) (Uchar.utf_decode_uchar d);
        at := !at + Uchar.utf_decode_length d;
        incr i
      end
    done;
    !i
  in
  Sedlexing.create ~bytes_per_char:Uchar.utf_8_byte_length refill

let stream ~file text =
  Diag.register_source file text;
  let buf = lexbuf_of_utf8 text in
  Sedlexing.set_filename buf file;
  let last = ref None in
  fun () ->
    match !last with
    | Some eof -> eof
    | None ->
        let raw =
          try next buf with
          | Unclosed (msg, s, e) -> Diag.error (Loc.make s e) "%s" msg
          | Lex_error msg ->
              let s, e = Sedlexing.lexing_positions buf in
              Diag.error (Loc.make s e) "%s" msg
          | Sedlexing.MalFormed ->
              let s, e = Sedlexing.lexing_positions buf in
              Diag.error (Loc.make s e) "invalid UTF-8 input"
        in
        let s, e = Sedlexing.lexing_positions buf in
        let tok = { raw; loc = Loc.make s e } in
        if raw = Eof then last := Some tok;
        tok

let tokenize ~file text =
  let next = stream ~file text in
  let rec loop acc =
    let tok = next () in
    if tok.raw = Eof then Array.of_list (List.rev (tok :: acc)) else loop (tok :: acc)
  in
  loop []
