(* Parse.string never raises: random token soup (directives, braces,
   operators, keywords, identifiers) gives Ok or a located Error. *)
open Camlray_lang

let words =
  [| "#declare"; "#local"; "#if"; "#else"; "#end"; "#while"; "#for"; "#macro"; "#switch"; "#case";
     "#break"; "#include"; "#undef"; "#ifdef"; "#version"; "#debug"; "#fopen"; "#read"; "#write";
     "{"; "}"; "("; ")"; "["; "]"; "<"; ">"; ","; ";"; "="; "+"; "-"; "*"; "/"; "?"; ":"; "&"; "|";
     "!"; "."; "x"; "1"; "0.5"; "-2"; "\"s\""; "A"; "B"; "M"; "sphere"; "plane"; "pigment";
     "rgb"; "color"; "function"; "spline"; "array"; "array[2]"; "sin"; "concat"; "str"; "seed";
     "rand"; "camera"; "light_source"; "texture"; "finish"; "transform"; "rotate"; "scale";
     "defined"; "dimensions"; "version"; "clock"; "/*"; "*/"; "//"; "\n" |]

let gen =
  QCheck.Gen.(
    map (fun l -> String.concat " " l) (list_size (int_range 0 40) (map (Array.get words) (int_bound (Array.length words - 1)))))

let options =
  { Parse.default_options with
    limits = { Supplier.default_limits with max_loop_iterations = 200; max_macro_depth = 20 } }

let prop =
  QCheck.Test.make ~name:"random token soup: Ok or a located error, never an exception" ~count:1500
    (QCheck.make ~print:(fun s -> s) gen)
    (fun text ->
      match Parse.string ~options text with
      | Ok _ -> true
      | Error d -> d.Diag.msg <> "" && not (Scn.contains d.msg "internal error"))


(* Folding arithmetic runs (Fold) changes nothing the parser reads: the
   same scene, or the same error message, with folding on and off. The
   expressions mix what folds (numbers, float names, + - * /, signs,
   parentheses, sin(...)) with what must not (members, macros that end
   mid-expression, directives inside an expression, comparisons, vectors,
   rand), in the places a run may start. *)
let plain_prelude =
  "#declare A = 3; #declare B = -0.5; #declare V = <1, 2, 3>; #declare R = seed(7);\n\
   #declare Arr = array[3] { 4, 5, 6 }\n\
   #macro M() 3 #end #macro P() 2 * #end #macro Q() 1 + 2 #end #macro S(X) X * 2 #end\n"

(* with a deprecated name, names are looked up at every reading (see
   Fold.replay): both ways are tested *)
let prelude = plain_prelude ^ "#declare deprecated \"use A\" D = 4;\n"

let expr_gen =
  QCheck.Gen.(
    sized_size (int_bound 12)
    @@ fix (fun self n ->
           let leaf =
             oneof_list
               [ "1"; "2.5"; "0"; "A"; "B"; "pi"; "V.x"; "V.z"; "Arr[1]"; "Arr[A - 2]"; "M()"; "-3";
                 "clock"; "rand(R)"; "1e300"; "Q()"; "S(2)"; "S(A + 1)"; "D"; "M(1)"; "Arr[7]";
                 "<1, A, 2>"; "<A, B>"; "<0, 1, 2, 3, 4, 5>"; "<1 2 3>"; "<1, 2,>" ]
           in
           if n <= 0 then leaf
           else
             let sub = self (n / 2) in
             oneof_weighted
               [ (3, leaf);
                 (5, map3 (fun a op b -> a ^ " " ^ op ^ " " ^ b) sub (oneof_list [ "+"; "-"; "*"; "/" ]) sub);
                 (1, map (fun a -> "-" ^ a) sub); (1, map (fun a -> "+ " ^ a) sub);
                 (2, map (fun a -> "(" ^ a ^ ")") sub);
                 (2, map2 (fun f a -> f ^ "(" ^ a ^ ")") (oneof_list [ "sin"; "abs"; "sqrt"; "int"; "asin"; "ln" ]) sub);
                 (1, map2 (fun a b -> "max(" ^ a ^ ", " ^ b ^ ")") sub sub);
                 (1, map2 (fun a b -> "pow(" ^ a ^ ", " ^ b ^ ")") sub sub);
                 (1, map3 (fun a b c -> "(" ^ a ^ " < " ^ b ^ " ? " ^ c ^ " : 2)") sub sub sub);
                 (1, map (fun a -> "(" ^ a ^ ").y") sub); (1, map (fun a -> "P() " ^ a) sub);
                 (1, map2 (fun a b -> a ^ " #if (A > 2) * " ^ b ^ " #end") sub sub);
                 (1, map (fun a -> "(" ^ a ^ " + <" ^ a ^ ", 1, 2>).x") sub) ]))

let context_gen =
  QCheck.Gen.(
    let e = expr_gen in
    oneof
      [ map2 (fun a b -> Printf.sprintf "sphere { <%s, 0, 1>, %s }" a b) e e;
        map3 (fun a b c -> Printf.sprintf "sphere { <%s %s %s> 1 }" a b c) e e e;
        map2 (fun a b -> Printf.sprintf "#declare X = %s; sphere { 0, X + %s }" a b) e e;
        map (fun a -> Printf.sprintf "#declare X = %s\nsphere { 0, X }" a) e;
        map2 (fun a b -> Printf.sprintf "#declare Y = array[2] { %s, %s } sphere { Y[0], Y[1] }" a b) e e;
        map2 (fun a b -> Printf.sprintf "#for (I, 0, %s) sphere { <I * %s, 0, 0>, 1 } #end" a b) e e;
        map2 (fun a b -> Printf.sprintf "#if (%s < %s) sphere { 0, 1 } #end" a b) e e;
        map2 (fun a b -> Printf.sprintf "sphere { 0, 1 scale %s translate <%s, 0, 0> }" a b) e e;
        map2 (fun a b -> Printf.sprintf "sphere { 0, S(%s) + %s }" a b) e e;
        map (fun a -> Printf.sprintf "mesh2 { vertex_vectors { 3, <0,0,0>, <%s, 0, 0>, <0, 1, 0> } \
                                      face_indices { 1, <0, 1, 2> } }" a) e;
        (* vectors read again in loops and macro bodies (Fold.replay),
           their names changing value, type or status between readings *)
        map2 (fun a b -> Printf.sprintf "#for (I, 0, 3) sphere { <%s, I, 1>, %s } #end" a b) e e;
        map (fun a -> Printf.sprintf
               "#for (I, 0, 3) #if (I = 2) #declare A = <1, 2, 3>; #end sphere { <A * I, %s, 0>, 1 } #end" a) e;
        map (fun a -> Printf.sprintf "#macro T(X) sphere { <X, %s, 1>, 1 } #end T(1) T(2) T(<1, 2, 3>) T(A) T(B)" a) e;
        map (fun a -> Printf.sprintf
               "#for (I, 0, 2) #if (I = 1) #declare deprecated \"no\" A = 2; #end sphere { <A, I, %s>, 1 } #end" a) e;
        map (fun a -> Printf.sprintf "#for (I, 0, 2) #if (I = 1) #undef A #end sphere { <A, I, %s>, 1 } #end" a) e;
        map (fun a -> Printf.sprintf "#declare J = 0; #while (J < 3) sphere { <J, %s, 0>, 1 } #declare J = J + 1; #end" a) e;
        map (fun a -> Printf.sprintf
               "#macro W(X) <X, %s, 1> #end sphere { W(1), 1 } #declare Z = W(2) + 1; sphere { Z, W(A).x } \
                #if (W(3).x > 0) sphere { 0, 1 } #end" a) e;
        map2 (fun a b -> Printf.sprintf
                "#for (I, 0, 2) #declare C = <I, %s, 1>; #declare D2 = <%s, I>; sphere { C, D2.x } #end" a b) e e ])

(* the scene (or error) and the warnings, in order, and what the scene
   wrote with #write, with folding (Fold) and plain expressions evaluated
   without the parser (Quick) on or off *)
let written = "quick-write.txt"

let read_with ~fold ~quick text =
  let options = { options with Parse.fold_arithmetic = fold; quick_eval = quick } in
  if Sys.file_exists written then Sys.remove written;
  let r, warnings =
    Diag.collect_warnings (fun () ->
        match Parse.string ~options text with
        | Ok s -> (try Ok (Printer.scene s) with e -> Ok ("unprintable: " ^ Printexc.to_string e))
        | Error d -> Error (Diag.to_string d))
  in
  let w =
    if Sys.file_exists written then "\nwritten: " ^ In_channel.with_open_bin written In_channel.input_all else ""
  in
  match r with Ok s -> Ok (s ^ warnings ^ w) | Error s -> Error (s ^ warnings ^ w)

(* folding on or off, as the parser reads without Quick *)
let read_folded fold text = read_with ~fold ~quick:false text

let folding_changes_nothing gen name count =
  let run = read_folded in
  QCheck.Test.make ~name ~count (QCheck.make ~print:(fun s -> s) gen) (fun text ->
      let a = run true text and b = run false text in
      if a <> b then
        QCheck.Test.fail_reportf "folded:\n%s\nnot folded:\n%s"
          (match a with Ok s | Error s -> s) (match b with Ok s | Error s -> s);
      true)

(* Cases the generators reach only by chance: an error in the arithmetic
   before a name whose reading fails (the arithmetic's error comes first,
   as in the parser), vectors of every length, and a '<' that compares. *)
let fold_cases =
  Alcotest.test_case "folding arithmetic: fixed cases read the same" `Quick (fun () ->
      let run = read_folded in
      List.iter
        (fun text ->
          List.iter (fun prelude ->
          let text = prelude ^ text in
          let a = run true text and b = run false text in
          if a <> b then
            Alcotest.failf "%s\nfolded: %s\nnot folded: %s" text
              (match a with Ok s | Error s -> s) (match b with Ok s | Error s -> s))
          [ prelude; plain_prelude ])
        [ "sphere { 0, sqrt(-1) + M(1) }"; "sphere { <ln(0), M(1), 0>, 1 }";
          "sphere { <1, 2, 3> * 2, A < 4 }"; "sphere { 0, (A < 2 + 1) + 1 }";
          "sphere { <1>, 1 }"; "sphere { <1, 2>, 1 }"; "sphere { <1, 2, 3, 4, 5>, 1 }";
          "sphere { <1, 2, 3, 4, 5, 6>, 1 }"; "sphere { <1, 2, 3>.y, 1 }";
          "sphere { 0, <1, 2, 3>.y + 1 }"; "sphere { -<1, 2, 3>, 1 }";
          "sphere { 0, 1 pigment { rgb <1, 0.5, 0.25> * 2 } }";
          "sphere { 0, 1 pigment { rgb <1, 0.5, 0.25> + <0, 0, 1> } }";
          "#declare X = <1, 2, 3> sphere { X, 1 }"; "sphere { 0, D + 1 }";
          "sphere { 0, 1 translate <A, 1/0, 2> }";
          "#for (I, 0, 3) sphere { <1/(I - 2), I, 0>, 1 } #end";
          "#for (I, 0, 3) sphere { <I, 2, 0>, 1 } #if (I = 1) #declare A = \"s\"; #end sphere { <A, I, 0>, 1 } #end";
          "#for (I, 0, 2) #declare V = <I, clock, version>; sphere { V, 1 } #end";
          "#macro T(X) sphere { <X, 1, 1>, 1 } #end T(1) T(2) T(3) T(<1, 2, 3>)";
          "#declare X = 5; #macro U() sphere { <X, 1, 1>, 1 } #end U() U() #macro V(X) U() #end V(7) U() V(8)";
          "#declare X = 5; #for (I, 0, 3) sphere { <X, I, 1>, 1 } #if (I = 1) #undef X #declare X = 9; #end #end";
          "#for (I, 0, 3) sphere { <I, 0, 1>, 1 } #if (I = 1) #local I = 7; #end #end";
          "#for (I, 0, 3) sphere { <1/(I - 1), 2/(I*0 - 0) + 1/I, -(I/(2 - I))>, 1 } #end";
          "#for (I, 0, 2) sphere { <sin(1/I), I, 0>, 1 } #end" ])

(* A loop that reaches the token limit while its vectors are read again
   from what was kept of them stops at the same token, with the same
   message. *)
let replay_limit =
  Alcotest.test_case "folding arithmetic, quick evaluation: the token limit inside vectors and phrases read again" `Quick (fun () ->
      let texts =
        [ "#for (I, 0, 99) #declare V = <I, I + 1, I * 2 - 3>; #end sphere { V, 1 }";
          (* Quick's phrases: a #while's condition, #local, #if, macro arguments *)
          "#macro N(X, Y) #local Z = X + Y * 2; #if (Z > 3 & Z < 1000) sphere { 0, Z } #end #end\n\
           #declare J = 0; #while (J < 30) N(J, J + 1) #declare J = J + 1; #end" ]
      in
      List.iter (fun text -> List.iter
        (fun max_tokens ->
          let run fold =
            let limits = { options.limits with max_tokens } in
            match Parse.string ~options:{ options with Parse.fold_arithmetic = fold; quick_eval = fold; limits } text with
            | Ok s -> Ok (Printer.scene s)
            | Error d -> Error (Diag.to_string d)
          in
          let a = run true and b = run false in
          (match b with Error _ -> () | Ok _ -> if max_tokens < 1000 then Alcotest.fail "no limit reached");
          if a <> b then
            Alcotest.failf "limit %d\nfolded: %s\nnot folded: %s" max_tokens
              (match a with Ok s | Error s -> s) (match b with Ok s | Error s -> s))
        [ 40; 41; 42; 43; 44; 45; 50; 77; 100; 333; 1000; 100_000 ]) texts)

(* Quick: the expressions of directives read without the parser. The
   generated expressions (above) in every directive Quick reads them for,
   and phrases of its own: strings, comparisons, logic, ternaries,
   members, declared functions, vectors with a trailing comma, calls
   that fail. *)
(* expressions Quick reads whole, mostly: every operator and primary of
   the grammar's expr, names of every kind, warnings (a division by zero),
   errors (a string in arithmetic, a bad member) and a state (rand) whose
   order shows; now and then what it leaves to the parser (a macro, an
   array element, components without commas) *)
let qexpr_gen =
  QCheck.Gen.(
    sized_size (int_bound 10)
    @@ fix (fun self n ->
           let leaf =
             oneof_weighted
               [ (12, oneof_list
                        [ "1"; "2.5"; "0"; "A"; "B"; "pi"; "V.x"; "V"; "-3"; "clock"; "rand(R)"; "1/0"; "x";
                          "<1, A, 2>"; "<A, B>"; "<A, 1, 2, 3, 4>"; "F(A, 1)"; "G(2).y"; "version"; "image_width";
                          "(A < B)"; "Str"; "\"s\""; "V.t"; "V.u"; "<1, 2,>"; "sqrt(-1)"; "vlength(V)" ]);
                 (1, oneof_list [ "M()"; "Arr[1]"; "D"; "<1 2 3>"; "U"; "S(1)"; "<1>" ]) ]
           in
           if n <= 0 then leaf
           else
             let sub = self (n / 2) in
             let op = oneof_list [ "+"; "-"; "*"; "/"; "<"; "<="; ">"; ">="; "="; "!="; "&"; "|" ] in
             oneof_weighted
               [ (3, leaf);
                 (6, map3 (fun a o b -> a ^ " " ^ o ^ " " ^ b) sub op sub);
                 (1, map (fun a -> "-" ^ a) sub); (1, map (fun a -> "+" ^ a) sub); (1, map (fun a -> "!" ^ a) sub);
                 (2, map (fun a -> "(" ^ a ^ ")") sub); (1, map (fun a -> "(" ^ a ^ ").x") sub);
                 (1, map3 (fun a b c -> a ^ " ? " ^ b ^ " : " ^ c) sub sub sub);
                 (1, map3 (fun a b c -> "<" ^ a ^ ", " ^ b ^ ", " ^ c ^ ">") sub sub sub);
                 (1, map2 (fun f a -> f ^ "(" ^ a ^ ")") (oneof_list [ "sin"; "abs"; "int"; "str"; "vnormalize" ]) sub);
                 (1, map2 (fun a b -> "max(" ^ a ^ ", " ^ b ^ ")") sub sub);
                 (1, map2 (fun a b -> "F(" ^ a ^ ", " ^ b ^ ")") sub sub) ]))

let quick_gen =
  QCheck.Gen.(
    let e = oneof_weighted [ (4, qexpr_gen); (1, expr_gen) ] in
    let s =
      oneof_list
        [ "\"ab\""; "str(A, 0, 16)"; "str(V.y * B, -3, 2)"; "concat(\"x\", str(1/3, 0, 5))"; "Str";
          "chr(65)"; "substr(\"hello\", 2, 3)"; "str(<1,2>, 0, 0)"; "\"a\" + 1"; "vstr(3, V, \",\", 0, 1)" ]
    in
    let c =
      oneof_list
        [ "A < B"; "A = 3"; "A != B & B < 0"; "(A > 2) | 0"; "!A"; "\"ab\" = Str"; "Str != \"x\"";
          "A < 2 ? 1 : 0"; "V.x >= 1"; "1 < 2 < 3"; "A ? B : \"s\""; "F(A, 2) > 1"; "V < 2" ]
    in
    oneof
      [ map2 (fun a b -> Printf.sprintf "#declare X = %s; #local Y = %s; sphere { 0, X + Y }" a b) e e;
        map2 (fun a b -> Printf.sprintf "#declare X = %s; sphere { X, %s }" a b) s e;
        map3 (fun a b c -> Printf.sprintf "#if (%s) sphere { 0, %s } #elseif (%s) sphere { 0, 2 } #end" a b c) c e c;
        map2 (fun a b -> Printf.sprintf "#declare J = 0; #while (J < %s & J < 4) sphere { 0, J + %s } #declare J = J + 1; #end" a b) e e;
        map3 (fun a b c -> Printf.sprintf
               "#fopen Out \"quick-write.txt\" write #write (Out, %s, \"|\", %s, \"|\", %s, \"\\n\") #fclose Out" a b c) s e c;
        map2 (fun a b -> Printf.sprintf "#macro T(X, Y) sphere { X, Y } #end T(%s, %s)" a b) e e;
        map2 (fun a b -> Printf.sprintf "#macro T(X, Y) sphere { 0, 1 } #declare Z = concat(X, \"\"); #end T(%s, %s)" a b) s e;
        map2 (fun a b -> Printf.sprintf "#declare Y = array[3] { 1, 2, 3 } sphere { 0, Y[%s] + Y[%s] }" a b) e e;
        map2 (fun a b -> Printf.sprintf "#declare O = sphere { 0, 1 } #declare N = <0,0,0>; #declare P = trace(O, %s, <0, 0, 1> + %s, N); sphere { P, N.z }" a b) e e;
        map2 (fun a b -> Printf.sprintf "#switch (%s) #case (1) sphere { 0, 1 } #break #range (%s, 5) sphere { 0, 3 } #end" a b) e e;
        map2 (fun a b -> Printf.sprintf "#for (I, %s, %s) sphere { 0, I } #end" a b) e e;
        map3 (fun a b c -> Printf.sprintf "#declare X = %s ? %s : %s; sphere { 0, X }" a b c) c e e;
        map2 (fun a b -> Printf.sprintf "#declare X = A ? 1/0 + %s : rand(R) + 2/0 + %s; sphere { 0, X }" a b) e e;
        map2 (fun a b -> Printf.sprintf "#declare X = <%s, %s,>; sphere { X, 1 }" a b) e e;
        map2 (fun a b -> Printf.sprintf "#declare X = F(%s, %s) + G(1).y; sphere { 0, X }" a b) e e;
        map (fun a -> Printf.sprintf "#declare X = (%s).y + -+!0; sphere { 0, X }" a) e ])

let quick_prelude =
  prelude
  ^ "#declare Str = \"ab\"; #declare F = function(a, b) { a * b + 1 }\n\
     #declare G = function { transform { translate <1, 2, 3> } }\n"

let quick_changes_nothing name count =
  QCheck.Test.make ~name ~count
    (QCheck.make ~print:(fun s -> s) (QCheck.Gen.map (fun c -> quick_prelude ^ c) quick_gen))
    (fun text ->
      let here = Sys.getcwd () in
      Sys.chdir (Helpers.temp_dir ());
      Fun.protect ~finally:(fun () -> Sys.chdir here) (fun () ->
          let differ a b what =
            if a <> b then
              QCheck.Test.fail_reportf "%s:\n%s\nand:\n%s" what
                (match a with Ok s | Error s -> s) (match b with Ok s | Error s -> s)
          in
          (* Quick on and off, folding held either way (folding has
             differences of its own: an expression the parser reads
             again to try a left-out separator warns again where it was
             not folded) *)
          List.iter
            (fun fold ->
              differ (read_with ~fold ~quick:true text) (read_with ~fold ~quick:false text)
                (if fold then "quick evaluation on and off, folding on" else "quick evaluation on and off, folding off"))
            [ false; true ];
          true))

let fold_props =
  [ quick_changes_nothing "quick evaluation: the same scene, error, warnings and #write as the parser" 3000;
    folding_changes_nothing (QCheck.Gen.map (fun c -> prelude ^ c) context_gen)
      "folding arithmetic: the same scene or error as without" 5000;
    folding_changes_nothing (QCheck.Gen.map (fun c -> plain_prelude ^ c) context_gen)
      "folding arithmetic, no deprecated name: the same scene or error as without" 3000;
    folding_changes_nothing gen "folding arithmetic: token soup reads the same" 5000 ]

(* A directive after an item of a mesh2 block inside a #declare makes the
   parser run its actions ahead (Supplier's probe for a missing ';'): the
   item must not be added twice. *)
let mesh2_items_once =
  Alcotest.test_case "mesh2 items: directives between them in a #declare" `Quick (fun () ->
      let read text =
        match Parse.string ~options text with
        | Ok s -> Printer.scene s
        | Error d -> Alcotest.failf "%s" (Diag.to_string d)
      in
      let with_directives =
        "#declare X = 1;\n\
         #declare M = mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>\n\
           #if (X) , <0,1,0> #else , <0,2,0> #end #debug \"\"\n\
           , <1,1,0> #declare Y = 2; } face_indices { 2, <0,1,2> #debug \"\" , <1,3,2> #local Z = 1; } }\n\
         object { M }"
      and plain =
        "#declare X = 1;\n\
         #declare M = mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0>, <1,1,0> }\n\
           face_indices { 2, <0,1,2>, <1,3,2> } }\n\
         object { M }"
      in
      Alcotest.(check string) "the same mesh" (read plain) (read with_directives))

(* POV-Ray's commas are optional in mesh2 blocks (its mesh2.pov leaves
   out some); blob components take moves, turns and scales *)
let optional_commas_blob_moves =
  Alcotest.test_case "mesh2 items without commas; blob components moved" `Quick (fun () ->
      let read text =
        match Parse.string text with
        | Ok s -> Printer.scene s
        | Error d -> Alcotest.failf "%s" (Diag.to_string d)
      in
      Alcotest.(check string) "mesh2"
        (read "mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0>, <1,1,0> } face_indices { 2, <0,1,2>, <1,3,2> } }")
        (read "mesh2 { vertex_vectors { 4 <0,0,0>, <1,0,0> <0,1,0>\n <1,1,0> } face_indices { 2 <0,1,2> <1,3,2>, } }");
      Alcotest.(check string) "blob"
        (read "blob { threshold 0.5 sphere { vrotate(<1,0,0>, y*90) * 2, 2, 1 }\n\
                      cylinder { vrotate(0, z*90) + y, vrotate(2*x, z*90) + y, 0.5, 2 } }")
        (read "blob { threshold 0.5 sphere { <1,0,0>, 1, 1 rotate y*90 scale 2 } cylinder { 0, 2*x, 0.5, 2 rotate z*90 translate y } }");
      (* a stretch places the component: its field is taken in its own space *)
      Alcotest.(check string) "stretched"
        (read "blob { sphere { 0, 1, 1 matrix <1,0,0, 0,2,0, 0,0,1, 0,0,0> } }")
        (read "blob { sphere { 0, 1, 1 scale <1,2,1> } }"))

(* POV-Ray's own example scenes (Debian's povray-examples, installed by
   make test's setup): each reads the same, warnings included, with
   folding (and vectors read again) and Quick on and off. *)
let pov_examples_dir = "/usr/share/doc/povray/examples"

let rec pov_files dir =
  Sys.readdir dir |> Array.to_list |> List.sort compare
  |> List.concat_map (fun f ->
         let p = Filename.concat dir f in
         if Sys.is_directory p then pov_files p else if Filename.check_suffix f ".pov" then [ p ] else [])

let pov_examples_fold =
  Alcotest.test_case "folding arithmetic: POV-Ray's example scenes read the same" `Slow (fun () ->
      if not (Sys.file_exists pov_examples_dir) then print_endline "povray-examples not installed: skipped"
      else begin
        let read fold file =
          (* a small image: some scenes loop over its pixels *)
          let options =
            { Parse.default_options with fold_arithmetic = fold; quick_eval = fold; image_width = 40; image_height = 30 }
          in
          let r, warnings =
            Diag.collect_warnings (fun () ->
                match Parse.file ~options file with
                | Ok (s, _) -> (try Printer.scene s with e -> "unprintable: " ^ Printexc.to_string e)
                | Error d -> "error: " ^ Diag.to_string d)
          in
          r ^ warnings
        in
        let files = pov_files pov_examples_dir in
        (* some scenes #write files into the current folder: a temporary one *)
        let here = Sys.getcwd () in
        Sys.chdir (Helpers.temp_dir ());
        Fun.protect ~finally:(fun () -> Sys.chdir here) (fun () ->
            List.iter
              (fun f ->
                let a = read true f and b = read false f in
                if a <> b then Alcotest.failf "%s reads differently folded:\n%s\nand not:\n%s" f a b)
              files);
        Alcotest.(check bool) "some scenes" true (List.length files > 300)
      end)

(* light_group: bare global_lights is on; the transformations move the
   whole group; the printed scene reads back to itself (a light_group
   printed inside object { }, which takes its other modifiers) *)
let light_groups =
  Alcotest.test_case "light_group: global_lights, transformations, printed back" `Quick (fun () ->
      let read text =
        match Parse.string text with
        | Ok s -> Printer.scene s
        | Error d -> Alcotest.failf "%s" (Diag.to_string d)
      in
      let g = "light_source { <0,5,0>, rgb 1 } sphere { 0, 1 pigment { rgb 1 } }" in
      Alcotest.(check string) "bare global_lights is on"
        (read ("light_group { " ^ g ^ " global_lights on }"))
        (read ("light_group { " ^ g ^ " global_lights }"));
      Alcotest.(check string) "the last global_lights counts"
        (read ("light_group { " ^ g ^ " }"))
        (read ("light_group { " ^ g ^ " global_lights on global_lights off }"));
      if read ("light_group { " ^ g ^ " }") = read ("light_group { " ^ g ^ " global_lights on }") then
        Alcotest.fail "global_lights on is not printed";
      Alcotest.(check string) "transformations in order"
        (read ("light_group { " ^ g ^ " matrix <2,0,0, 0,2,0, 0,0,2, 1,0,0> }"))
        (read ("light_group { " ^ g ^ " scale 2 translate x }"));
      let text =
        "#declare G = light_group { " ^ g ^ " light_group { light_source { x, rgb <1,0,0> } box { -1, 1 } } global_lights }\n\
         object { G pigment { rgb 0.5 } translate y no_shadow }\n\
         difference { light_group { " ^ g ^ " } sphere { y, 1 } }"
      in
      let once = read text in
      Alcotest.(check string) "printed, read back" once (read once))

let tests = ("parse", fold_cases :: replay_limit :: mesh2_items_once :: optional_commas_blob_moves :: light_groups :: pov_examples_fold :: List.map QCheck_alcotest.to_alcotest (prop :: fold_props))
