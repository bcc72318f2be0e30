(* Objects: shapes, CSG, object modifiers. *)
(* (the OCaml header, opening Camlray and Gram, is in grammar_lang.mly) *)

%token SPHERE PLANE OBJECT NO_SHADOW HOLLOW NO_IMAGE NO_REFLECTION NO_RADIOSITY DOUBLE_ILLUMINATE
%token BOX CYLINDER CONE TORUS DISC TRIANGLE SMOOTH_TRIANGLE MESH MESH2 OPEN STURM
%token VERTEX_VECTORS NORMAL_VECTORS UV_VECTORS FACE_INDICES NORMAL_INDICES UV_INDICES
%token TEXTURE_LIST INSIDE_VECTOR
%token UNION INTERSECTION DIFFERENCE MERGE CLIPPED_BY BOUNDED_BY
%token BICUBIC_PATCH TYPE FLATNESS U_STEPS V_STEPS SOR INTERIOR_TEXTURE
%token QUARTIC CUBIC POLY QUADRIC TEXT TTF INTERNAL BLOB THRESHOLD STRENGTH COMPONENT HIERARCHY PRISM
%token <string> SPLINE_KIND
%token JULIA_FRACTAL QUATERNION HYPERCOMPLEX CUBE MAX_ITERATION PRECISION SLICE
%token LATHE SUPERELLIPSOID POLYGON HEIGHT_FIELD WATER_LEVEL SMOOTH
%token <string> IMAGE_KIND

%token LIGHT_GROUP GLOBAL_LIGHTS
%token ISOSURFACE CONTAINED_BY ACCURACY MAX_GRADIENT EVALUATE MAX_TRACE ALL_INTERSECTIONS

%%

%public object_:
  | SPHERE LBRACE c = param COMMA? r = param ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Sdl.Sphere (v3 $loc(c) c, fl $loc(r) r)) ms }
  | PLANE LBRACE n = param COMMA? d = param ms = list(object_mod) RBRACE
      { let nv = v3 $loc(n) n in
        if Vec3.length nv = 0. then Diag.error (loc $loc(n)) "a plane's normal cannot be zero";
        Shapes.obj (loc $loc) (Sdl.Plane (nv, fl $loc(d) d)) ms }
  | BOX LBRACE a = param COMMA? b = param ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Sdl.Box (v3 $loc(a) a, v3 $loc(b) b)) ms }
  | CYLINDER LBRACE a = param COMMA? b = param COMMA? r = param ms = list(object_mod) RBRACE
      { let r = fl $loc(r) r in
        Shapes.obj (loc $loc) (Sdl.Cone { base = v3 $loc(a) a; base_r = r; top = v3 $loc(b) b;
                                          top_r = r; open_ = false; cylinder = true }) ms }
  | CONE LBRACE a = param COMMA? ra = param COMMA? b = param COMMA? rb = param
    ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Sdl.Cone { base = v3 $loc(a) a; base_r = fl $loc(ra) ra;
                                          top = v3 $loc(b) b; top_r = fl $loc(rb) rb;
                                          open_ = false; cylinder = false }) ms }
  | TORUS LBRACE r1 = param COMMA? r2 = param ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Sdl.Torus (fl $loc(r1) r1, fl $loc(r2) r2)) ms }
  | DISC LBRACE c = param COMMA? n = param COMMA? r = param h = ioption(preceded(COMMA, param))
    ms = list(object_mod) RBRACE
      { let hole = match h with Some h -> fl $loc(h) h | None -> 0. in
        Shapes.obj (loc $loc) (Sdl.Disc { center = v3 $loc(c) c; normal = v3 $loc(n) n;
                                          radius = fl $loc(r) r; hole }) ms }
  | TRIANGLE LBRACE a = param COMMA? b = param COMMA? c = param ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Sdl.Triangle (v3 $loc(a) a, v3 $loc(b) b, v3 $loc(c) c)) ms }
  | SMOOTH_TRIANGLE LBRACE a = param COMMA? na = param COMMA? b = param COMMA? nb = param
    COMMA? c = param COMMA? nc = param ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc)
          (Sdl.Smooth_triangle (v3 $loc(a) a, v3 $loc(b) b, v3 $loc(c) c,
                                v3 $loc(na) na, v3 $loc(nb) nb, v3 $loc(nc) nc)) ms }
  | MESH LBRACE ts = nonempty_list(mesh_triangle) ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Shapes.mesh (loc $loc) ts) ms }
  | MESH2 LBRACE bs = nonempty_list(mesh2_block) ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Shapes.mesh2 (loc $loc) bs) ms }
  (* a declared object again, with more modifiers (POV-Ray takes any
     object's identifier there, as in object { }) *)
  | MESH LBRACE o = OBJECT_ID ms = list(object_mod) RBRACE
      { List.fold_left (fun o f -> f o) { o with Sdl.loc = loc $loc } ms }
  | MESH2 LBRACE o = OBJECT_ID ms = list(object_mod) RBRACE
      { List.fold_left (fun o f -> f o) { o with Sdl.loc = loc $loc } ms }
  | QUARTIC LBRACE c = param ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Shapes.algebraic (loc $loc(c)) "quartic" 4 c) ms }
  | CUBIC LBRACE c = param ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Shapes.algebraic (loc $loc(c)) "cubic" 3 c) ms }
  | POLY LBRACE n = param COMMA? c = param ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Shapes.poly (loc $loc(n)) (loc $loc(c)) n c) ms }
  | QUADRIC LBRACE a = param COMMA? b = param COMMA? c = param COMMA? j = param ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Shapes.quadric (v3 $loc(a) a) (v3 $loc(b) b) (v3 $loc(c) c) (fl $loc(j) j)) ms }
  | TEXT LBRACE TTF f = string_arg COMMA? s = string_arg COMMA? th = param COMMA? off = param ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Shapes.text (loc $loc(f)) f s (fl $loc(th) th) (v3 $loc(off) off)) ms }
  (* POV-Ray's built-in fonts, the files Debian installs with its includes *)
  | TEXT LBRACE INTERNAL n = param COMMA? s = string_arg COMMA? th = param COMMA? off = param ms = list(object_mod) RBRACE
      { let f = Shapes.internal_font (loc $loc(n)) (Value.to_int (loc $loc(n)) n) in
        Shapes.obj (loc $loc) (Shapes.text (loc $loc(n)) f s (fl $loc(th) th) (v3 $loc(off) off)) ms }
  | BLOB LBRACE items = list(blob_item) ms = list(object_mod) RBRACE
      { let threshold = List.fold_left (fun t i -> match i with `Threshold x -> x | `Comp _ -> t) 1. items in
        let comps = List.filter_map (function `Comp c -> Some c | `Threshold _ -> None) items in
        Shapes.obj (loc $loc) (Sdl.Blob (threshold, comps)) ms }
  | PRISM LBRACE kinds = list(SPLINE_KIND) h1 = param COMMA? h2 = param COMMA? n = param
    pts = list(prism_point) ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc)
          (Shapes.prism (loc $loc) kinds (fl $loc(h1) h1) (fl $loc(h2) h2) (loc $loc(n), Value.to_int (loc $loc(n)) n) pts) ms }
  | SOR LBRACE n = param pts = list(prism_point) ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Shapes.sor (loc $loc) (loc $loc(n), Value.to_int (loc $loc(n)) n) pts ~open_:false) ms }
  | LATHE LBRACE kinds = list(SPLINE_KIND) n = param pts = list(prism_point) ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Shapes.lathe (loc $loc) kinds (loc $loc(n), Value.to_int (loc $loc(n)) n) pts) ms }
  | POLYGON LBRACE n = param pts = list(prism_point) ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Shapes.polygon (loc $loc) (loc $loc(n), Value.to_int (loc $loc(n)) n) pts) ms }
  | HEIGHT_FIELD LBRACE src = hf_source os = list(hf_option) ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Shapes.height_field src os) ms }
  | BICUBIC_PATCH LBRACE os = list(patch_option) pts = list(prism_point) ms = list(object_mod) RBRACE
      { (* POV-Ray's default steps: 0 (one cell: two triangles; measured) *)
        let steps k = List.fold_left (fun acc (k', n) -> if k = k' then n else acc) 0 os in
        Shapes.obj (loc $loc)
          (Shapes.bicubic_patch (loc $loc) ~u_steps:(steps `U) ~v_steps:(steps `V)
             (Array.of_list (List.map (fun (l, p) -> Value.to_vec3 l p) pts))) ms }
  | JULIA_FRACTAL LBRACE c = param ws = list(julia_word) ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Shapes.julia (loc $loc(c)) c ws) ms }
  | SUPERELLIPSOID LBRACE e = param ms = list(object_mod) RBRACE
      { Shapes.obj (loc $loc) (Shapes.superellipsoid (loc $loc(e)) e) ms }
  | ISOSURFACE LBRACE f = FUNCTION_LIT items = list(iso_item) RBRACE
      { Shapes.isosurface (loc $loc) (loc $loc(f)) f items }
  | UNION LBRACE cs = csg_body RBRACE { Shapes.csg (loc $loc) Sdl.Union cs }
  | INTERSECTION LBRACE cs = csg_body RBRACE { Shapes.csg (loc $loc) Sdl.Intersection cs }
  | DIFFERENCE LBRACE cs = csg_body RBRACE { Shapes.csg (loc $loc) Sdl.Difference cs }
  | MERGE LBRACE cs = csg_body RBRACE { Shapes.csg (loc $loc) Sdl.Merge cs }
  (* POV-Ray reads the objects (light sources among them) first, then
     only transformations and global_lights *)
  | LIGHT_GROUP LBRACE cs = list(object_) ms = list(light_group_mod) RBRACE
      { Shapes.light_group (loc $loc) cs ms }
  | OBJECT LBRACE o = OBJECT_ID ms = list(object_mod) RBRACE
      { List.fold_left (fun o f -> f o) { o with Sdl.loc = loc $loc } ms }
  | OBJECT LBRACE o = object_ ms = list(object_mod) RBRACE { List.fold_left (fun o f -> f o) o ms }

(* an isosurface's parameters and its modifiers, in any order *)
iso_item:
  | CONTAINED_BY LBRACE BOX LBRACE a = param COMMA? b = param RBRACE RBRACE
      { Shapes.Iso_container (Isosurface.Box (v3 $loc(a) a, v3 $loc(b) b)) }
  | CONTAINED_BY LBRACE SPHERE LBRACE c = param COMMA? r = param RBRACE RBRACE
      { Shapes.Iso_container (Shapes.iso_sphere (loc $loc(r)) (v3 $loc(c) c) (fl $loc(r) r)) }
  | THRESHOLD e = param { Shapes.Iso_threshold (fl $loc(e) e) }
  | ACCURACY e = param { Shapes.Iso_accuracy (loc $loc(e), fl $loc(e) e) }
  | MAX_GRADIENT e = param { Shapes.Iso_max_gradient (loc $loc(e), fl $loc(e) e) }
  | EVALUATE a = param COMMA? b = param COMMA? c = param
      { Shapes.Iso_evaluate (loc $loc, (fl $loc(a) a, fl $loc(b) b, fl $loc(c) c)) }
  | MAX_TRACE e = param { Shapes.Iso_max_trace (loc $loc(e), Value.to_int (loc $loc(e)) e) }
  | ALL_INTERSECTIONS { Shapes.Iso_max_trace (loc $loc, max_int) }
  | m = object_mod { Shapes.Iso_mod m }

julia_word:
  | QUATERNION { `Quat }
  | HYPERCOMPLEX { `Hyper (loc $loc) }
  | f = FUNC { if f = "sqr" then `Sqr else Diag.error (loc $loc) "%s (a julia_fractal function) is not supported by camlray: sqr and cube are" f }
  | CUBE { `Cube }
  | MAX_ITERATION n = param { `Iter (loc $loc(n), n) }
  | PRECISION p = param { `Prec (loc $loc(p), p) }
  | SLICE v = param COMMA d = param { `Slice (loc $loc, v, d) }

prism_point: COMMA? p = param { (loc $loc(p), p) }

blob_item:
  | THRESHOLD e = param { `Threshold (fl $loc(e) e) }
  | SPHERE LBRACE c = param COMMA? r = param COMMA? STRENGTH? s = param ms = list(blob_mod) RBRACE
      { `Comp (Shapes.blob_component (loc $loc) ms
                 (Shapes.blob_sphere (loc $loc) (v3 $loc(c) c) (fl $loc(r) r) (fl $loc(s) s))) }
  | CYLINDER LBRACE a = param COMMA? b = param COMMA? r = param COMMA? STRENGTH? s = param
    ms = list(blob_mod) RBRACE
      { `Comp (Shapes.blob_component (loc $loc) ms
                 (Shapes.blob_cylinder (loc $loc) (v3 $loc(a) a) (v3 $loc(b) b) (fl $loc(r) r) (fl $loc(s) s))) }
  | COMPONENT s = param COMMA? r = param COMMA? c = param
      { `Comp (Shapes.blob_component (loc $loc) []
                 (Shapes.blob_sphere (loc $loc) (v3 $loc(c) c) (fl $loc(r) r) (fl $loc(s) s))) }

(* what a blob's sphere or cylinder takes after its numbers, in any order
   (POV-Ray's Parse_Blob_Element_Mods): transformations, which move the
   texture written before them, and its own texture *)
blob_mod:
  | t = transformation { Sdl.transform_obj t }
  | TEXTURE LBRACE t = texture_body RBRACE
      { fun (o : Sdl.obj) -> { o with texture = Some (match o.texture with
          | Some layers -> Gram.layered (loc $loc) ~above:t ~below:layers | None -> t) } }
  | PIGMENT LBRACE p = pigment_edit RBRACE { with_texture $loc (fun l -> { l with Texture.pigment = p l.pigment }) }
  | NORMAL LBRACE n = normal_edit RBRACE { with_texture $loc (fun l -> { l with Texture.normal = n l.normal }) }
  | FINISH LBRACE f = finish_edit RBRACE { with_texture $loc (fun l -> { l with Texture.finish = f l.finish }) }

(* children and modifiers, in any order (POV-Ray wants the children
   first; modifiers apply in order to the whole CSG) *)
csg_body: items = list(csg_item) { items }

csg_item:
  | o = object_ { `Child o }
  | m = object_mod { `Mod m }

light_group_mod:
  | t = transformation { `Xf t }
  | GLOBAL_LIGHTS { `Global true }
  | GLOBAL_LIGHTS b = param { `Global (Value.to_bool (loc $loc(b)) b) }

mesh_triangle:
  | TRIANGLE LBRACE a = param COMMA? b = param COMMA? c = param uv = ioption(triangle_uv)
    t = ioption(mesh_texture) RBRACE
      { Shapes.mesh_triangle (loc $loc) [| v3 $loc(a) a; v3 $loc(b) b; v3 $loc(c) c |] uv t }
  | SMOOTH_TRIANGLE LBRACE a = param COMMA? na = param COMMA? b = param COMMA? nb = param
    COMMA? c = param COMMA? nc = param uv = ioption(triangle_uv) t = ioption(mesh_texture) RBRACE
      { Shapes.mesh_triangle (loc $loc)
          [| v3 $loc(a) a; v3 $loc(na) na; v3 $loc(b) b; v3 $loc(nb) nb; v3 $loc(c) c; v3 $loc(nc) nc |] uv t }

(* a mesh triangle's corners' uv: uv_vectors UA, UB, UC *)
triangle_uv:
  | UV_VECTORS a = param COMMA? b = param COMMA? c = param
      { [ (loc $loc(a), a); (loc $loc(b), b); (loc $loc(c), c) ] }

mesh_texture: TEXTURE LBRACE t = texture_body RBRACE { t }

mesh2_block:
  | VERTEX_VECTORS LBRACE n = param vs = items RBRACE { Shapes.vertex_vectors (loc $loc) n vs }
  | NORMAL_VECTORS LBRACE n = param vs = items RBRACE { Shapes.normal_vectors (loc $loc) n vs }
  | UV_VECTORS LBRACE n = param vs = items RBRACE { Shapes.uv_vectors (loc $loc) n vs }
  | FACE_INDICES LBRACE n = param vs = items RBRACE { Shapes.face_indices (loc $loc) n vs }
  | NORMAL_INDICES LBRACE n = param vs = items RBRACE { Shapes.normal_indices (loc $loc) n vs }
  | UV_INDICES LBRACE n = param vs = items RBRACE { Shapes.uv_indices (loc $loc) n vs }
  | TEXTURE_LIST LBRACE n = param ts = list(texture_list_item) RBRACE
      { Shapes.texture_list (loc $loc) n ts }

texture_list_item: COMMA? t = mesh_texture { t }

(* ", item, item ..." with an optional trailing comma. Left recursive: a
   mesh's 10^5 items are reduced one by one into the block's items (kept
   flat, see Shapes.items), not held on the parser's stack to the closing
   brace. *)
items: b = items_rev ioption(COMMA) { b }

items_rev:
  | { Shapes.items () }
  (* commas are optional, as everywhere in POV-Ray (its mesh2.pov leaves
     some out: after the count, between vectors) *)
  | b = items_rev COMMA? p = param { Shapes.add_item b $startpos(p) $endpos(p) p }

%public object_mod:
  | t = transformation { Sdl.transform_obj t }
  | INTERIOR_TEXTURE LBRACE t = texture_body RBRACE
      { fun (o : Sdl.obj) -> { o with inner = Some (match o.inner with
          | Some layers -> Gram.layered (loc $loc) ~above:t ~below:layers | None -> t) } }
  | TEXTURE LBRACE t = texture_body RBRACE
      { fun (o : Sdl.obj) ->
          let t = if o.flags land Sdl.uv_mapping <> 0 then Texture.uv ~turns:false t else t in
          { o with texture = Some (match o.texture with
          | Some layers -> Gram.layered (loc $loc) ~above:t ~below:layers | None -> t) } }
  | PIGMENT LBRACE p = pigment_edit RBRACE
      { fun (o : Sdl.obj) ->
          let uv = o.flags land Sdl.uv_mapping <> 0 in
          with_texture $loc (fun l -> { l with Texture.pigment = (let q = p l.pigment in if uv then Pigment.uv q else q) }) o }
  (* the textures, pigments and normals written after it are uv-mapped;
     POV-Ray refuses it after the object's own texture *)
  | UV_MAPPING
      { fun (o : Sdl.obj) ->
          if o.texture <> None then Diag.error (loc $loc) "uv_mapping must come before the object's texture, pigment, normal or finish";
          { o with flags = o.flags lor Sdl.uv_mapping } }
  | FINISH LBRACE f = finish_edit RBRACE
      { with_texture $loc (fun l -> { l with Texture.finish = f l.finish }) }
  | INTERIOR LBRACE i = interior_body RBRACE { fun (o : Sdl.obj) -> { o with interior = Some i } }
  | NO_SHADOW { fun (o : Sdl.obj) -> { o with no_shadow = true } }
  | ps = photons_block { Gram.object_photons ps }
  | k = object_flag %prec below_shift { fun (o : Sdl.obj) -> { o with flags = o.flags lor k } }
  | k = object_flag b = param
      { let on = Value.to_bool (loc $loc(b)) b in
        fun (o : Sdl.obj) -> { o with flags = (if on then o.flags lor k else o.flags land lnot k) } }
  | HOLLOW %prec below_shift { fun (o : Sdl.obj) -> { o with hollow = true } }
  | HOLLOW b = param { let h = Value.to_bool (loc $loc) b in fun (o : Sdl.obj) -> { o with hollow = h } }
  | OPEN { Shapes.set_open (loc $loc) }
  | STURM { fun o -> o }
  | HIERARCHY %prec below_shift { fun o -> o }
  | HIERARCHY e = param { ignore e; fun o -> o }
  | INVERSE { Shapes.inverse }
  | INSIDE_VECTOR v = param { Shapes.inside_vector (loc $loc) (v3 $loc(v) v) }
  | CLIPPED_BY LBRACE cs = nonempty_list(object_) RBRACE { Shapes.clipped cs }
  | BOUNDED_BY LBRACE cs = nonempty_list(object_) RBRACE { Shapes.bounded cs }
  | BOUNDED_BY LBRACE CLIPPED_BY RBRACE { Shapes.bound_by_clip (loc $loc) }
  | CLIPPED_BY LBRACE BOUNDED_BY RBRACE { Shapes.clip_by_bound (loc $loc) }

hf_source:
  | f = FUNCTION_SIZED { let (w, h, fn, text) = f in Shapes.Hf_fn (loc $loc, w, h, fn, text) }
  | k = hf_kind f = string_arg { Shapes.Hf_file (loc $loc, Some k, f) }
  | f = string_arg { Shapes.Hf_file (loc $loc(f), None, f) }

hf_kind:
  | PNG { "png" }
  | k = IMAGE_KIND { k }

hf_option:
  | SMOOTH { Shapes.Hf_smooth }
  | WATER_LEVEL e = param { Shapes.Hf_water (loc $loc(e), fl $loc(e) e) }

object_flag:
  | NO_IMAGE { Sdl.no_image }
  | NO_REFLECTION { Sdl.no_reflection }
  (* POV-Ray hides the object from its radiosity's gather rays (mc
     mode's indirect light still sees it) *)
  | NO_RADIOSITY { Sdl.no_radiosity }
  (* an object's radiosity { importance ... }: read and ignored *)
  | RADIOSITY LBRACE rs = list(rad_item) RBRACE { Gram.object_radiosity (loc $loc) rs; 0 }
  | DOUBLE_ILLUMINATE { Sdl.double_illuminate }

(* type 0|1, flatness: how POV-Ray keeps its subpatches (camlray always
   cuts down to the steps); u_steps, v_steps *)
patch_option:
  | TYPE e = param
      { let t = Value.to_int (loc $loc(e)) e in
        if t <> 0 && t <> 1 then Diag.error (loc $loc(e)) "a bicubic_patch's type is 0 or 1, found %d" t;
        (`T, t) }
  | FLATNESS e = param { ignore (fl $loc(e) e); (`F, 0) }
  (* the corners' uv coordinates: uv_mapping is not supported, so they
     change nothing *)
  | UV_VECTORS a = param COMMA? b = param COMMA? c = param COMMA? d = param
      { List.iter (fun (l, v) -> ignore (Value.to_vec3 l v)) [ (loc $loc(a), a); (loc $loc(b), b); (loc $loc(c), c); (loc $loc(d), d) ];
        (`F, 0) }
  | U_STEPS e = param { (`U, Value.to_int (loc $loc(e)) e) }
  | V_STEPS e = param { (`V, Value.to_int (loc $loc(e)) e) }
