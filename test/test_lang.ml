(* Scene language properties: the parser never raises on any input, and
   expressions evaluate as an independent model of POV-Ray's rules says
   (precedence, '&' and '|' sharing one level, '=' with tolerance, '?:'). *)
open Camlray_lang

(* ---------- robustness ---------- *)

let corpus = lazy (Fuzz_gen.corpus ())

let no_exception =
  QCheck.Test.make ~name:"random token streams and mutated scenes: Ok or Error, never an exception"
    ~count:2000
    (QCheck.make ~print:(fun s -> s) (fun st -> Fuzz_gen.input st (Lazy.force corpus)))
    (fun text ->
      match Fuzz_gen.with_stderr_silenced (fun () -> Fuzz_gen.check ~timeout:10 text) with
      | Fuzz_gen.Accepted | Fuzz_gen.Rejected -> true
      | Fuzz_gen.Hung -> QCheck.Test.fail_reportf "still parsing after 10 s"
      | Fuzz_gen.Crashed e -> QCheck.Test.fail_reportf "exception %s" e)

(* ---------- expressions: a model and a printer ---------- *)

type e =
  | Num of float
  | Neg of e
  | Not of e
  | Bin of string * e * e
  | Cond of e * e * e
  | Fn of string * e list
  | Member of e list * e * string  (** (<a,b,c> * k).x *)

let level = function
  | Cond _ -> 0
  | Bin (("&" | "|"), _, _) -> 1
  | Bin (("<" | "<=" | "=" | "!=" | ">=" | ">"), _, _) -> 2
  | Bin (("+" | "-"), _, _) -> 3
  | Bin _ -> 4
  | Neg _ | Not _ -> 5
  | Num _ | Fn _ | Member _ -> 6

let rec print e =
  let wrap l x = if level x < l then "(" ^ print x ^ ")" else print x in
  let wrap_right l x = if level x <= l then "(" ^ print x ^ ")" else print x in
  match e with
  | Num f -> Printf.sprintf "%.17g" f
  | Neg x -> "-" ^ wrap 5 x
  | Not x -> "!" ^ wrap 5 x
  | Bin (op, a, b) ->
      let l = level e in
      Printf.sprintf "%s %s %s" (wrap l a) op (wrap_right l b)
  | Cond (c, a, b) -> Printf.sprintf "%s ? %s : %s" (wrap 1 c) (print a) (print b)
  | Fn (f, args) -> Printf.sprintf "%s(%s)" f (String.concat ", " (List.map print args))
  | Member (v, k, m) ->
      (* like povray, camlray reads vector components without comparisons
         or logic operators: those need parentheses *)
      Printf.sprintf "(<%s> * %s).%s" (String.concat ", " (List.map (wrap 3) v)) (wrap 5 k) m

exception Undefined

let b x = if x then 1. else 0.

let rec eval = function
  | Num f -> f
  | Neg x -> -.eval x
  | Not x -> b (eval x = 0.)
  | Bin (op, x, y) -> (
      let x = eval x and y = eval y in
      match op with
      | "+" -> x +. y
      | "-" -> x -. y
      | "*" -> x *. y
      | "/" -> if Float.abs y < 1e-6 then raise Undefined else x /. y
      | "<" -> b (x < y)
      | "<=" -> b (x <= y)
      | ">" -> b (x > y)
      | ">=" -> b (x >= y)
      | "=" -> b (Float.abs (x -. y) <= 1e-10)
      | "!=" -> b (Float.abs (x -. y) > 1e-10)
      | "&" -> b (x <> 0. && y <> 0.)
      | "|" -> b (x <> 0. || y <> 0.)
      | _ -> assert false)
  | Cond (c, x, y) -> if eval c <> 0. then eval x else eval y
  | Fn (f, args) -> (
      let a = List.map eval args in
      match (f, a) with
      | "abs", [ x ] -> Float.abs x
      | "floor", [ x ] -> Float.floor x
      | "int", [ x ] -> Float.trunc x
      | "mod", [ x; y ] -> if Float.abs y < 1e-6 then raise Undefined else Float.rem x y
      | "min", x :: r -> List.fold_left Float.min x r
      | "max", x :: r -> List.fold_left Float.max x r
      | "sin", [ x ] -> Float.sin x
      | _ -> assert false)
  | Member (v, k, m) ->
      let k = eval k in
      let i = match m with "x" -> 0 | "y" -> 1 | _ -> 2 in
      eval (List.nth v i) *. k

let gen_e =
  QCheck.Gen.(
    sized_size (int_bound 6)
    @@ fix (fun self n ->
           let leaf = map (fun f -> Num f) (oneof_list [ 0.; 1.; 2.; 0.5; 3.25; 10.; 1e-3 ]) in
           if n = 0 then leaf
           else
             let sub = self (n - 1) in
             oneof_weighted
               [
                 (1, leaf);
                 (1, map (fun x -> Neg x) sub);
                 (1, map (fun x -> Not x) sub);
                 ( 5,
                   map3
                     (fun op a b -> Bin (op, a, b))
                     (oneof_list [ "+"; "-"; "*"; "/"; "<"; "<="; ">"; ">="; "="; "!="; "&"; "|" ])
                     sub sub );
                 (1, map3 (fun c a b -> Cond (c, a, b)) sub sub sub);
                 ( 1,
                   oneof
                     [
                       map (fun x -> Fn ("abs", [ x ])) sub;
                       map (fun x -> Fn ("floor", [ x ])) sub;
                       map (fun x -> Fn ("int", [ x ])) sub;
                       map (fun x -> Fn ("sin", [ x ])) sub;
                       map2 (fun x y -> Fn ("mod", [ x; y ])) sub sub;
                       map3 (fun x y z -> Fn ("min", [ x; y; z ])) sub sub sub;
                       map2 (fun x y -> Fn ("max", [ x; y ])) sub sub;
                     ] );
                 ( 1,
                   map3
                     (fun (a, b') (c, k) m -> Member ([ a; b'; c ], k, m))
                     (pair sub sub) (pair sub sub) (oneof_list [ "x"; "y"; "z" ]) );
               ]))

let radius_of text =
  match Parse.string text with
  | Ok { Sdl.items = [ Sdl.Object { shape = Sdl.Sphere (_, r); _ } ]; _ } -> Ok r
  | Ok _ -> Error "unexpected scene"
  | Error d -> Error (Diag.to_string d)

let close a b =
  (Float.is_nan a && Float.is_nan b) || a = b
  || Float.abs (a -. b) <= 1e-9 *. (1. +. Float.abs a +. Float.abs b)

let round_trip =
  QCheck.Test.make ~name:"expressions: printed, parsed by #declare, equal to the model" ~count:1000
    (QCheck.make ~print:print gen_e) (fun e ->
      match eval e with
      | exception Undefined -> QCheck.assume_fail ()
      | want -> (
          let text = Printf.sprintf "#declare X = %s;\nsphere { 0, X }\n" (print e) in
          match radius_of text with
          | Ok got ->
              close want got || QCheck.Test.fail_reportf "model %.17g, camlray %.17g" want got
          | Error m -> QCheck.Test.fail_reportf "%s" m))

(* ---------- units ---------- *)

let expect_error text fragment () =
  match Parse.string text with
  | Ok _ -> Alcotest.failf "expected an error containing %S" fragment
  | Error d ->
      let m = Diag.to_string d in
      let n = String.length fragment in
      let rec has i = i + n <= String.length m && (String.sub m i n = fragment || has (i + 1)) in
      if not (has 0) then Alcotest.failf "error %S does not contain %S" m fragment

let rand_sequence () =
  (* printed by povray 3.7: str(rand(seed(0)), 0, 12) four times *)
  let text =
    "#declare S = seed(0);\n#declare A = rand(S); #declare B = rand(S); #declare C = rand(S);\n\
     sphere { <A, B, C>, rand(S) }\n"
  in
  match Parse.string text with
  | Ok { Sdl.items = [ Sdl.Object { shape = Sdl.Sphere (c, r); _ } ]; _ } ->
      let near a b = Alcotest.(check (float 5e-13)) "rand" a b in
      near 0.000002874294 c.x;
      near 0.466563684509 c.y;
      near 0.249070228834 c.z;
      near 0.965876042136 r
  | Ok _ -> Alcotest.fail "unexpected scene"
  | Error d -> Alcotest.fail (Diag.to_string d)

let std_includes () =
  List.iter
    (fun inc ->
      match Parse.string (Printf.sprintf "#include \"colors.inc\"\n#include %S\n" inc) with
      | Ok _ -> ()
      | Error d -> Alcotest.failf "%s: %s" inc (Diag.to_string d))
    [ "colors.inc"; "textures.inc"; "finish.inc"; "metals.inc"; "glass.inc"; "woods.inc";
      "stones.inc"; "golds.inc"; "transforms.inc"; "math.inc"; "shapes.inc" ]

let declared_use () =
  let text =
    "#include \"colors.inc\"\n#include \"finish.inc\"\n#include \"metals.inc\"\n\
     #declare P = pigment { Red }\n#declare T = texture { T_Chrome_1A }\n\
     #declare O = sphere { 0, 1 texture { T } }\n\
     object { O scale 2 }\nsphere { 0, 1 pigment { P } finish { Shiny reflection 0.2 } }\n"
  in
  match Parse.string text with
  | Ok { Sdl.items = [ Sdl.Object a; Sdl.Object b ]; _ } ->
      Alcotest.(check bool) "object keeps its texture" true (a.texture <> None);
      (match b.texture with
      | Some (l :: _) ->
          Alcotest.(check (float 1e-12)) "Shiny's specular kept" 1. l.finish.specular;
          Alcotest.(check (float 1e-12)) "reflection added" 0.2 l.finish.reflection.rmin.r
      | _ -> Alcotest.fail "no texture")
  | Ok _ -> Alcotest.fail "unexpected scene"
  | Error d -> Alcotest.fail (Diag.to_string d)

(* reflection { MIN MAX }: the comma is optional, as POV-Ray reads it
   (its gamma_showcase.pov writes reflection { 0.0 1.0 fresnel on }); a
   sign after MIN is still a subtraction *)
let reflection_without_comma () =
  let refl text =
    match Parse.string ("sphere { 0, 1 finish { reflection { " ^ text ^ " } } }") with
    | Ok { Sdl.items = [ Sdl.Object o ]; _ } -> (
        match o.texture with
        | Some (l :: _) -> (l.finish.reflection.rmin.r, l.finish.reflection.rmax.r)
        | _ -> Alcotest.fail "no texture")
    | Ok _ -> Alcotest.fail "unexpected scene"
    | Error d -> Alcotest.fail (Diag.to_string d)
  in
  let pair = Alcotest.(pair (float 1e-12) (float 1e-12)) in
  Alcotest.check pair "comma" (0.1, 0.7) (refl "0.1, 0.7");
  Alcotest.check pair "no comma" (0.1, 0.7) (refl "0.1 0.7");
  Alcotest.check pair "no comma, fresnel" (0.0, 1.0) (refl "0.0 1.0 fresnel on");
  Alcotest.check pair "rgb, no comma" (0.2, 0.5) (refl "rgb 0.2 rgb 0.5");
  Alcotest.check pair "minus is arithmetic" (0.5, 0.5) (refl "0.7 -0.2")

(* Layered textures where POV-Ray 3.7 allows them (a plain texture over
   plain ones, also under an object's uv_mapping, and a texture-level
   uv_mapping of a layered texture), and its two refusals (checked in
   POV-Ray 3.7.0: "Cannot layer over a patterned texture", "Cannot layer
   a patterned texture over another"), located at the texture on top *)
let layering () =
  let layers text =
    match Parse.string text with
    | Ok { Sdl.items = [ Sdl.Object o ]; _ } -> (
        match o.texture with Some l -> List.length l | None -> 0)
    | Ok _ -> Alcotest.fail "unexpected scene"
    | Error d -> Alcotest.fail (Diag.to_string d)
  in
  let refused text =
    match Parse.string text with
    | Error d -> d
    | Ok _ -> Alcotest.failf "accepted: %s" text
  in
  let plain = "texture { pigment { rgbt <1, 0, 0, 0.5> } }" in
  let checker = "texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }" in
  let uv = "texture { uv_mapping pigment { checker rgb 0 rgb 1 } }" in
  Alcotest.(check int) "plain over plain" 2 (layers ("sphere { 0, 1 " ^ plain ^ " " ^ plain ^ " }"));
  Alcotest.(check int) "object uv_mapping" 2 (layers ("sphere { 0, 1 uv_mapping " ^ plain ^ " " ^ plain ^ " }"));
  Alcotest.(check int) "uv_mapping of a layered texture" 2
    (layers ("#declare T = " ^ plain ^ " " ^ plain ^ "\nsphere { 0, 1 texture { uv_mapping T } }"));
  Alcotest.(check int) "uv-mapped pigment in a plain texture" 2
    (layers ("sphere { 0, 1 texture { pigment { uv_mapping checker rgb 0 rgb 1 } } " ^ plain ^ " }"));
  let over = "cannot layer over a patterned texture" and under = "cannot layer a patterned texture over another" in
  (* the message, and the line of the texture on top *)
  let check what msg line text =
    let d = refused text in
    Alcotest.(check string) (what ^ ": message") msg d.msg;
    Alcotest.(check int) (what ^ ": line") line d.loc.start.pos_lnum
  in
  check "over a checker texture" over 2 ("sphere { 0, 1 " ^ checker ^ "\n" ^ plain ^ " }");
  check "uv_mapping on top" under 2 ("sphere { 0, 1 " ^ plain ^ "\n" ^ uv ^ " }");
  check "over uv_mapping" over 2 ("sphere { 0, 1 " ^ uv ^ "\n" ^ plain ^ " }");
  check "both patterned" over 2 ("sphere { 0, 1 " ^ checker ^ "\n" ^ uv ^ " }");
  check "in a material" under 2 ("sphere { 0, 1 material { " ^ plain ^ "\n" ^ uv ^ " } }");
  check "interior_texture" under 2
    ("sphere { 0, 1 " ^ plain ^ " interior_texture { pigment { rgb 0 } }\ninterior_texture { " ^ String.sub checker 10 (String.length checker - 10) ^ " }");
  check "#declare" over 2 ("#declare T = " ^ checker ^ "\n" ^ plain ^ "\nsphere { 0, 1 texture { T } }");
  (* a pigment, finish or normal written on the object changes the top
     layer: refused over a patterned texture too *)
  check "finish after a checker texture" over 2 ("sphere { 0, 1 " ^ checker ^ "\nfinish { phong 1 } }");
  check "pigment after a checker texture" over 2 ("sphere { 0, 1 " ^ checker ^ "\npigment { rgb 1 } }");
  check "normal after uv_mapping" over 2 ("sphere { 0, 1 " ^ uv ^ "\nnormal { bumps 1 } }");
  Alcotest.(check int) "finish after a plain texture" 1 (layers ("sphere { 0, 1 " ^ plain ^ " finish { phong 1 } }"))

(* mesh2 items: vectors of three are read straight from the block's
   store, every other form through its value; both give the same mesh *)
let mesh2_items () =
  let text =
    "mesh2 { vertex_vectors { 5, <0, 0, 0>, 2, <1, 2, 3, 4>, <0.5, 0.25, 0.125>, <9, 8, 7> }\n\
     face_indices { 3, <0, 1, 2>, 1, <2, 3, 4, 0>, <4, 0, 1>, 2, 0, 0 }\n\
     texture_list { 3, texture { pigment { rgb 1 } } texture { pigment { rgb 0.5 } } texture { pigment { rgb 0 } } } }\n"
  in
  match Parse.string text with
  | Ok { Sdl.items = [ Sdl.Object { shape = Sdl.Mesh m; _ } ]; _ } ->
      Alcotest.(check (list (float 0.))) "vertices: triples, a float made a vector, a 4-vector cut to 3"
        [ 0.; 0.; 0.; 2.; 2.; 2.; 1.; 2.; 3.; 0.5; 0.25; 0.125; 9.; 8.; 7. ]
        (Float.Array.to_list m.verts);
      Alcotest.(check (array int)) "faces: triples and a 4-vector's first three" [| 0; 1; 2; 2; 3; 4; 4; 0; 1 |] m.faces;
      Alcotest.(check (array int)) "texture indices after faces" [| 1; -1; 2 |] m.face_textures
  | Ok _ -> Alcotest.fail "unexpected scene"
  | Error d -> Alcotest.fail (Diag.to_string d)

(* a mesh2's texture_list textures are written in the mesh's space and
   move with it, as a texture given to the mesh does (POV-Ray renders
   both scenes alike; camlray's list textures stayed put: 23.7 dB) *)
let texture_list_moves () =
  let scene tex =
    Printf.sprintf
      "#version 3.7;\nglobal_settings { assumed_gamma 1 }\ncamera { location <0, 0, -4> look_at 0 }\n\
       light_source { <-5, 5, -10> rgb 1 }\n\
       #declare T = texture { pigment { granite color_map { [0 rgb 0] [1 rgb <0, 0.6, 0.6>] } scale 0.3 } }\n\
       object { mesh2 { vertex_vectors { 4, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0> } %s }\n\
      \  scale 1.5 rotate 20*z translate <0.3, 0.2, 0> }"
      tex
  in
  let a = Helpers.render_whitted ~width:24 ~height:18 (scene "texture_list { 1, texture { T } } face_indices { 2, <0, 1, 2>, 0, <0, 2, 3>, 0 }")
  and b = Helpers.render_whitted ~width:24 ~height:18 (scene "face_indices { 2, <0, 1, 2>, <0, 2, 3> } texture { T }") in
  let same = ref true and values = Hashtbl.create 16 in
  for y = 0 to 17 do
    for x = 0 to 23 do
      (* the same up to rounding: the list's texture is moved by the
         whole transformation at once, the object's step by step *)
      let (r1, g1, b1) = Helpers.pixel a x y and (r2, g2, b2) = Helpers.pixel b x y in
      if Float.abs (r1 -. r2) +. Float.abs (g1 -. g2) +. Float.abs (b1 -. b2) > 1e-9 then same := false;
      Hashtbl.replace values (Helpers.pixel b x y) ()
    done
  done;
  Alcotest.(check bool) "a patterned picture" true (Hashtbl.length values > 20);
  Alcotest.(check bool) "the same picture" true !same

(* rgb takes a whole expression, as POV-Ray's parser does: rgb 0.2 + 0.5
   is rgb 0.7 (it was rgb 0.2 plus 0.5 in all five channels, a colour
   half transparent: POV-Ray's incdemo/screen.pov's boxes) *)
let rgb_expression () =
  let f e = Scn.float ~prelude:"#declare C = rgb 0.2 + 0.5 * 0.5;\n#declare D = rgb <1, 0, 0> * 0.5 filter 0.3;" e in
  Scn.check_floats "rgb 0.2 + 0.5 * 0.5" [ 0.45; 0.45; 0.45; 0.; 0. ]
    [ f "C.red"; f "C.green"; f "C.blue"; f "C.filter"; f "C.transmit" ];
  Scn.check_floats "rgb <1, 0, 0> * 0.5 filter 0.3" [ 0.5; 0.; 0.; 0.3; 0. ]
    [ f "D.red"; f "D.green"; f "D.blue"; f "D.filter"; f "D.transmit" ];
  Scn.check_floats "rgb 0.2 + <0.5, 0, 0> (POV-Ray: 0.7 0.2 0)" [ 0.7; 0.2; 0. ]
    (let g = Scn.float ~prelude:"#declare H = rgb 0.2 + <0.5, 0, 0>;" in [ g "H.red"; g "H.green"; g "H.transmit" ]);
  (* as in POV-Ray, rgb starts a colour, not a term of a sum *)
  Scn.check_message "#declare E = 0.5 + rgb 0.2;" "found keyword rgb";
  (* no_radiosity: read, nothing to hide from in whitted mode *)
  ignore (Scn.parse "sphere { 0, 1 no_radiosity }")

let tests =
  ( "lang",
    [
      Alcotest.test_case "rgb takes a whole expression; no_radiosity read" `Quick rgb_expression;
      Alcotest.test_case "texture_list textures move with the mesh" `Quick texture_list_moves;
      Alcotest.test_case "rand matches povray" `Quick rand_sequence;
      Alcotest.test_case "standard includes parse" `Quick std_includes;
      Alcotest.test_case "declared identifiers reused" `Quick declared_use;
      Alcotest.test_case "reflection { MIN MAX } without a comma" `Quick reflection_without_comma;
      Alcotest.test_case "unsupported use reported" `Quick
        (expect_error
           "#declare Swirl = pigment { aoi color_map { [0 rgb 0] [1 rgb 1] } }\nsphere { 0, 1 pigment { Swirl } }\n"
           "Swirl uses aoi");
      Alcotest.test_case "unsupported keyword named" `Quick
        (expect_error "ovus { 1, 0.5 }\n" "ovus is not supported by camlray");
      Alcotest.test_case "mesh2 items of every form" `Quick mesh2_items;
      Alcotest.test_case "layered textures: allowed and refused as POV-Ray" `Quick layering;
      Alcotest.test_case "a face index that is not an integer" `Quick
        (expect_error "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\nface_indices { 1, <0, 1, 2.5> } }\n"
           "<string>:2:19: error: face index 2.5 is not an integer");
      Alcotest.test_case "include cycle" `Quick
        (expect_error "#include \"/dev/null/x\"\n" "cannot find include file");
    ]
    @ List.map QCheck_alcotest.to_alcotest [ no_exception; round_trip ] )
