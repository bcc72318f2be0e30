(* Objects: shapes, CSG, object modifiers. *)
(* (the OCaml header, opening Camlray and Gram, is in grammar_lang.mly) *)

%token SPHERE PLANE OBJECT NO_SHADOW HOLLOW

%%

%public object_:
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

%public object_mod:
  | t = transformation { Sdl.transform_obj t }
  | TEXTURE LBRACE t = texture_body RBRACE
      { fun (o : Sdl.obj) -> { o with texture = Some (match o.texture with
          | Some layers -> t @ layers | None -> t) } }
  | PIGMENT LBRACE p = pigment_body RBRACE
      { with_texture (fun l -> { l with Texture.pigment = p }) }
  | FINISH LBRACE f = finish_body RBRACE
      { with_texture (fun l -> { l with Texture.finish = f }) }
  | INTERIOR LBRACE i = interior_body RBRACE { fun (o : Sdl.obj) -> { o with interior = Some i } }
  | NO_SHADOW { fun (o : Sdl.obj) -> { o with no_shadow = true } }
  | HOLLOW %prec below_shift { fun (o : Sdl.obj) -> { o with hollow = true } }
  | HOLLOW b = param { let h = Value.to_bool (loc $loc) b in fun (o : Sdl.obj) -> { o with hollow = h } }
