(* The directive evaluator: declarations and scopes, conditionals, loops,
   switch, macros, arrays, includes. Answers checked against POV-Ray 3.7
   (the same directives printing through #debug). *)
open Camlray_lang

let floats = Scn.floats
let check = Scn.check_floats

let with_dir files f =
  let dir = Filename.concat (Filename.get_temp_dir_name ()) (Printf.sprintf "camlray-sup-%d" (Unix.getpid ())) in
  (try Unix.mkdir dir 0o755 with Unix.Unix_error (Unix.EEXIST, _, _) -> ());
  List.iter (fun (n, text) -> Out_channel.with_open_bin (Filename.concat dir n) (fun oc -> output_string oc text)) files;
  Fun.protect ~finally:(fun () ->
      List.iter (fun (n, _) -> try Sys.remove (Filename.concat dir n) with Sys_error _ -> ()) files;
      try Unix.rmdir dir with Unix.Unix_error _ -> ())
    (fun () -> f dir)

let parse_file path =
  match Parse.file path with
  | Ok (s, files) -> (s, files)
  | Error d -> Alcotest.failf "unexpected error:\n%s" (Diag.to_string d)

let radii (s : Sdl.scene) = List.map snd (Scn.spheres s)

let tests =
  ( "supplier",
    [
      Alcotest.test_case "#while sums 0..9" `Quick (fun () ->
          check "sum" [ 45. ]
            (floats "#declare I = 0; #declare S = 0;\n#while (I < 10) #declare S = S + I; #declare I = I + 1; #end\nsphere {0, S}"));
      Alcotest.test_case "#for with a negative step; the variable keeps the first value past the end" `Quick (fun () ->
          (* POV-Ray: 10741 and J = -2 *)
          check "for" [ 10741.; -2. ]
            (floats "#declare S = 0;\n#for (J, 10, 1, -3) #declare S = S * 10 + J; #end\nsphere {0, S} sphere {0, J}"));
      Alcotest.test_case "#for with a fractional step includes the end" `Quick (fun () ->
          check "steps" [ 0.; 0.25; 0.5; 0.75; 1. ] (floats "#for (K, 0, 1, 0.25) sphere {0, K} #end"));
      Alcotest.test_case "#for whose range is empty runs nothing" `Quick (fun () ->
          check "none" [ 7. ] (floats "#for (K, 3, 1) sphere {0, K} #end sphere {0, 7}"));
      Alcotest.test_case "#switch: #range, fall-through to the next #case, #else" `Quick (fun () ->
          check "switch 3" [ 24.; 5. ]
            (floats
               "#switch (3) #case (1) sphere {0,1} #break #range (2, 4) sphere {0,24}\n\
                #case (5) sphere {0,5} #break #else sphere {0,99} #end");
          check "switch 9" [ 99. ] (floats "#switch (9) #case (1) sphere {0,1} #else sphere {0,99} #end"));
      Alcotest.test_case "#if/#elseif/#else with nesting in skipped branches" `Quick (fun () ->
          check "elseif" [ 2. ]
            (floats "#if (0) #if (1) sphere{0,9} #end sphere{0,9} #elseif (1) sphere{0,2} #else sphere{0,9} #end"));
      Alcotest.test_case "#break leaves a #while loop" `Quick (fun () ->
          check "break" [ 3. ]
            (floats "#declare C = 0; #while (1) #declare C = C + 1; #if (C >= 3) #break #end #end sphere {0, C}"));
      Alcotest.test_case "recursive macro" `Quick (fun () ->
          check "6!" [ 720. ]
            (floats
               "#macro Fact(N) #if (N <= 1) #local R = 1; #else #local R = N * Fact(N - 1); #end R #end\n\
                #declare R = Fact(6); sphere {0, R}"));
      Alcotest.test_case "identifiers are passed to macros by reference" `Quick (fun () ->
          (* POV-Ray swaps X1 and X2 *)
          check "swap" [ 2.; 1. ]
            (floats
               "#macro Swap(a, b) #local T = a; #declare a = b; #declare b = T; #end\n\
                #declare X1 = 1; #declare X2 = 2; Swap(X1, X2) sphere {0, X1} sphere {0, X2}"));
      Alcotest.test_case "by reference: #local on a parameter, array elements, #undef stays local" `Quick (fun () ->
          (* POV-Ray 3.7: M: 5, N: 3, Z defined, E: 7 *)
          check "refs" [ 5.; 3.; 1.; 7. ]
            (floats
               "#macro M(a) #local a = 5; #end\n#macro N(a) #declare a = a + 1; #end\n#macro K(a) #undef a #end\n\
                #macro E(a) #declare a = 7; #end\n\
                #declare X = 1; M(X) #declare Y = 1; N(Y) N(Y) #declare Z = 1; K(Z)\n\
                #declare A = array[2] {1, 2}; E(A[0])\n\
                sphere {0, X} sphere {0, Y} sphere {0, defined(Z)} sphere {0, A[0]}"));
      Alcotest.test_case "an array passed to a macro is shared" `Quick (fun () ->
          check "fill" [ 3. ]
            (floats
               "#macro Fill(A, V) #for (I, 0, dimension_size(A, 1) - 1) #declare A[I] = V; #end #end\n\
                #declare Arr = array[4]; Fill(Arr, 3) sphere {0, Arr[3]}"));
      Alcotest.test_case "#local in a macro leaves the global alone" `Quick (fun () ->
          check "local" [ 1.; 5. ]
            (floats "#declare V = 1; #macro M() #local V = 5; sphere {0, V} #end M() sphere {0, V}" |> List.rev));
      Alcotest.test_case "#declare of a name local to the macro updates the local" `Quick (fun () ->
          check "declare local" [ 3.; 1. ]
            (floats "#declare V = 1; #macro M() #local V = 2; #declare V = 3; sphere {0, V} #end M() sphere {0, V}"));
      Alcotest.test_case "arrays: initialisers, dimensions, dimension_size, defined" `Quick (fun () ->
          check "arrays" [ 1.; 2.; 3.; 6.; 7.; 1.; 0.; 1.; 0. ]
            (floats
               "#declare A = array[3] { 1, 2, 3 };\n#declare B = array[2][3] { {1, 2, 3}, {4, 5, 6} };\n\
                #declare E = array[4]; #declare E[2] = 7;\n\
                sphere {0, dimensions(A)} sphere {0, dimensions(B)} sphere {0, dimension_size(B, 2)}\n\
                sphere {0, B[1][2]} sphere {0, E[2]}\n\
                sphere {0, defined(E[2])} sphere {0, defined(E[1])} sphere {0, defined(A)} sphere {0, defined(Nope)}"));
      Alcotest.test_case "#declare of a whole array copies it; of a function aliases it" `Quick (fun () ->
          check "copy" [ 1.; 9.; 6. ]
            (floats
               "#declare A = array[2] {1, 2}; #declare B = A; #declare B[0] = 9;\n\
                sphere {0, A[0]} sphere {0, B[0]}\n\
                #declare F = function { x * 2 } #declare G = F; sphere {0, G(3, 0, 0)}"));
      Alcotest.test_case "a string #declare may omit ';', even before a directive using it" `Quick (fun () ->
          check "strings" [ 4.; 3. ]
            (floats
               "#declare S = \"abc\"\n#declare T = concat(S, \"d\")\nsphere { 0, strlen(T) }\n\
                #declare U = str(1.5, 0, 1) sphere { 0, strlen(U) }"));
      Alcotest.test_case "a string array element may be declared without ';'" `Quick (fun () ->
          check "element" [ 2. ]
            (floats "#declare A = array[2] {\"a\", \"b\"}\n#declare S = A[1]\n#declare T = concat(S, \"c\")\nsphere { 0, strlen(T) }");
          Scn.check_message "#declare A = array[1] {1}\n#declare F = A[0]\nsphere { 0, F }" "ends with ';'");
      Alcotest.test_case "a float #declare may not omit ';'" `Quick (fun () ->
          Scn.check_message "#declare F = 1\nsphere { 0, F }" "ends with ';'");
      Alcotest.test_case "array initialisers may end with a comma" `Quick (fun () ->
          check "trailing" [ 2. ] (floats "#declare A = array[2] { 1, 2, }\nsphere { 0, A[1] }"));
      Alcotest.test_case "'default' without '#', a lone '#', form feeds" `Quick (fun () ->
          check "lexing" [ 1. ] (floats "default { finish { phong 1 } }\n# \012 sphere { 0, 1 }"));
      Alcotest.test_case "#fopen/#write then #read back until the file closes itself" `Quick (fun () ->
          (* relative to the current folder, where a scene may write *)
          let data = Printf.sprintf "camlray-fopen-%d.txt" (Unix.getpid ()) in
          Fun.protect ~finally:(fun () -> try Sys.remove data with Sys_error _ -> ()) (fun () ->
              let text =
                Printf.sprintf
                  "#fopen F %S write\n#write (F, 1.5, \",\", <1,2,3>, \",\", \"\\\"s\\\"\", \",\", -0.25)\n#fclose F\n\
                   #fopen G %S read\n#declare N = 0;\n\
                   #while (defined(G)) #read (G, V) #declare N = N + 1; #end\n\
                   sphere { 0, N } sphere { 0, V }\n"
                  data data
              in
              check "read" [ 4.; -0.25 ] (floats text);
              Alcotest.(check string) "written" "1.5,<1,2,3> ,\"s\",-0.25"
                (In_channel.with_open_bin data In_channel.input_all)));
      Alcotest.test_case "#fopen outside the allowed folders is refused" `Quick (fun () ->
          Scn.check_message "#fopen F \"/tmp/camlray-never.txt\" write" "is not allowed");
      Alcotest.test_case "#ifdef of an array element, #undef" `Quick (fun () ->
          check "ifdef" [ 2.; 4. ]
            (floats
               "#declare E = array[2]; #declare E[0] = 1;\n\
                #ifdef (E[1]) sphere {0,1} #else sphere {0,2} #end\n\
                #declare M = 1; #undef M #ifndef (M) sphere {0,4} #end"));
      Alcotest.test_case "array errors are located" `Quick (fun () ->
          Scn.check_message "#declare A = array[2]; sphere {0, A[2]}" "outside the array";
          Scn.check_message "#declare A = array[2]; sphere {0, A[1]}" "has not been set";
          Scn.check_message "#declare A = array[2] {1, 2, 3};" "too many initialisers");
      Alcotest.test_case "an include's #local disappears, its #declare stays" `Quick (fun () ->
          with_dir
            [ ("inc.inc", "#local L = 5;\n#declare G = 6;\n");
              ("main.pov", "#include \"inc.inc\"\n#ifdef (L) sphere {0, 1} #end sphere {0, G}\n") ]
            (fun dir ->
              let s, files = parse_file (Filename.concat dir "main.pov") in
              check "radii" [ 6. ] (radii s);
              Alcotest.(check int) "files read" 2 (List.length files)));
      Alcotest.test_case "an include file's #version stays in force after it (as in povray 3.7)" `Quick (fun () ->
          with_dir
            [ ("v.inc", "#version 3.5;\n#declare Inside = version;\n");
              ("main.pov", "#version 3.7;\n#include \"v.inc\"\nsphere {0, Inside} sphere {0, version}\n") ]
            (fun dir ->
              let s, _ = parse_file (Filename.concat dir "main.pov") in
              check "versions" [ 3.5; 3.5 ] (radii s)));
      Alcotest.test_case "an include cycle is an error" `Quick (fun () ->
          with_dir [ ("a.inc", "#include \"a.inc\"\n"); ("main.pov", "#include \"a.inc\"\n") ] (fun dir ->
              match Parse.file (Filename.concat dir "main.pov") with
              | Ok _ -> Alcotest.fail "expected an error"
              | Error d ->
                  if not (Scn.contains d.msg "include cycle") then Alcotest.failf "message %S" d.msg;
                  Alcotest.(check bool) "chain" true (d.chain <> [])));
      Alcotest.test_case "file_exists looks where #include looks" `Quick (fun () ->
          check "exists" [ 1.; 0. ]
            (floats "sphere {0, file_exists(\"colors.inc\")} sphere {0, file_exists(\"no-such.inc\")}"));
      Alcotest.test_case "#declare deprecated: the value is bound" `Quick (fun () ->
          check "deprecated" [ 2. ] (floats "#declare deprecated once \"old\" D = 2;\nsphere {0, D}"));
      Alcotest.test_case "a runaway #while stops at the iteration limit" `Quick (fun () ->
          let options =
            { Parse.default_options with
              limits = { Supplier.default_limits with max_loop_iterations = 100 } }
          in
          match Parse.string ~options "#while (1) #end" with
          | Ok _ -> Alcotest.fail "expected an error"
          | Error d -> if not (Scn.contains d.msg "iterations") then Alcotest.failf "message %S" d.msg);
      Alcotest.test_case "the object limit: loops, shared declarations, exponential trees" `Quick
        (fun () ->
          let options n =
            { Parse.default_options with
              limits = { Supplier.default_limits with max_objects = n } }
          in
          let expect n text where =
            match Parse.string ~options:(options n) text with
            | Ok _ -> Alcotest.failf "expected the object limit on %S" text
            | Error d ->
                if not (Scn.contains d.msg (Printf.sprintf "more than %d objects" n)) then
                  Alcotest.failf "message %S" d.msg;
                Alcotest.(check int) "line" where d.loc.start.pos_lnum
          in
          (* a loop inside one union stops at the object that passes the limit *)
          expect 50 "union {\n#for (i, 0, 1000) sphere { <i,0,0>, 1 } #end }" 2;
          (* declared once, placed many times: 11 nodes each *)
          let placed = "#declare U = union { #for (i, 0, 9) sphere { 0, 1 } #end }\n" in
          expect 100 (placed ^ "#for (k, 0, 9) object { U } #end") 2;
          (match Parse.string ~options:(options 110) (placed ^ "#for (k, 0, 9) object { U } #end") with
           | Ok _ -> ()
           | Error d -> Alcotest.failf "110 nodes are allowed: %s" d.msg);
          (* doubling 60 times stands for 2^60 objects: refused, not walked *)
          let doubling =
            "#declare U = sphere { 0, 1 }\n\
             #for (i, 1, 60) #declare U = union { object { U } object { U } } #end\n\
             object { U }"
          in
          expect 1000 doubling 3);
      Alcotest.test_case "tokens read on demand are those of the whole-file lexer; released ones are refused" `Quick
        (fun () ->
          let text = String.concat "\n" (List.init 4000 (fun i -> Printf.sprintf "sphere { <%d, 0, 0>, 0.5 }" i)) in
          let all = Lexer.tokenize ~file:"<t>" text in
          let toks = Toks.of_text ~file:"<t>" text in
          let n = Array.length all in
          Alcotest.(check bool) "many chunks" true (n > 10000 + (4 * Toks.margin));
          Array.iteri
            (fun i (tok : Lexer.token) ->
              let got = Toks.get toks i in
              if got.raw <> tok.raw || Loc.to_string got.loc <> Loc.to_string tok.loc then
                Alcotest.failf "token %d differs" i)
            all;
          Alcotest.(check bool) "last is there" true (Toks.mem toks (n - 1));
          Alcotest.(check bool) "none after it" false (Toks.mem toks n);
          Alcotest.(check bool) "past the end: Eof" true ((Toks.get toks (n + 10)).raw = Lexer.Eof);
          Toks.release toks 10000;
          let kept = 10000 - Toks.margin in
          Alcotest.(check bool) "kept" true ((Toks.get toks kept).raw = all.(kept).raw);
          match Toks.get toks 0 with
          | _ -> Alcotest.fail "a released token was returned"
          | exception Invalid_argument _ -> ());
      Alcotest.test_case "a long file: loops, macros and #if spanning thousands of tokens, tokens released" `Quick
        (fun () ->
          (* 6 tokens a line: each block below is more than two chunks *)
          let block = String.concat "\n" (List.init 2000 (fun _ -> "#declare S = S + 1;")) in
          let filler = String.concat "\n" (List.init 3000 (fun _ -> "sphere { 0, 1 }")) in
          let text =
            String.concat "\n"
              [ "#declare S = 0;"; filler; "#macro Add() "; block; "#end"; filler;
                "#declare I = 0; #while (I < 3)"; block; "#declare I = I + 1; #end";
                "#for (K, 1, 2)"; block; "#end"; "Add() Add()"; "#if (S > 0)"; block; "#end";
                filler; "sphere { 0, S }" ]
          in
          let radii = floats text in
          Alcotest.(check int) "spheres" 9001 (List.length radii);
          (* 3 + 2 + 2 runs of the block and the #if one: 8 x 2000 *)
          check "S" [ 16000. ] [ List.nth radii 9000 ]);
      Alcotest.test_case "unbounded macro recursion stops at the depth limit" `Quick (fun () ->
          Scn.check_message "#macro R() R() #end R()" "nested deeper");
      Alcotest.test_case "standard include files load" `Quick (fun () ->
          if Sys.file_exists Parse.pov_include_dir then
            List.iter
              (fun inc -> ignore (Scn.parse (Printf.sprintf "#version 3.7;\n#include \"%s\"\n" inc)))
              [ "colors.inc"; "consts.inc"; "finish.inc"; "metals.inc"; "golds.inc"; "math.inc";
                "transforms.inc"; "functions.inc"; "strings.inc"; "rand.inc"; "arrays.inc" ]);
          (* trace, inside, min_extent, max_extent: the answers POV-Ray 3.7
         prints through #debug for the same declarations *)
      Alcotest.test_case "min_extent and max_extent give POV-Ray's boxes" `Quick (fun () ->
          let ext decl =
            Scn.vec ~prelude:(decl ^ " #declare Lo = min_extent(O); #declare Hi = max_extent(O);") "Lo"
            @ Scn.vec ~prelude:(decl ^ " #declare Lo = min_extent(O); #declare Hi = max_extent(O);") "Hi"
          in
          check "sphere" [ -1.; 0.; 1.; 3.; 4.; 5. ] (ext "#declare O = sphere { <1,2,3>, 2 }");
          check ~eps:2e-6 "rotated box (corners turned, single precision)"
            [ -4.154212; -2.289059; -4.470682; 6.408264; 6.400375; 6.710400 ]
            (ext "#declare O = box { <-1,-2,-3>, <4,5,6> rotate <10,20,30> }");
          check "torus turned and stretched" [ -2.5; -5.; -0.5; 2.5; 5.; 0.5 ]
            (ext "#declare O = torus { 2, 0.5 rotate x*90 scale <1,2,1> }");
          check "difference: its first object's box" [ -1.; -1.; -1.; 1.; 1.; 1. ]
            (ext "#declare O = difference { box { -1, 1 } sphere { 0, 1.2 } }");
          check "scaled cylinder" [ -2.; 0.; -2.; 2.; 6.; 2. ]
            (ext "#declare O = cylinder { <0,0,0>, <0,3,0>, 1 scale 2 }");
          check "plane: unbounded" [ -1e10; -1e10; -1e10; 1e10; 1e10; 1e10 ] (ext "#declare O = plane { y, -1 }"));
      Alcotest.test_case "trace: the first crossing and its normal, zeros when it misses" `Quick (fun () ->
          let tr decl call =
            let prelude = decl ^ " #declare N = <9,9,9>; #declare I = " ^ call ^ ";" in
            Scn.vec ~prelude "I" @ Scn.vec ~prelude "N"
          in
          let s = "#declare S = sphere { <1,2,3>, 2 }" in
          check "from above" [ 1.; 4.; 3.; 0.; 1.; 0. ] (tr s "trace(S, <1,10,3>, -y, N)");
          let r = Float.sqrt 2. in
          check ~eps:1e-12 "from inside: the far side, outward normal"
            [ 1. +. r; 2. +. r; 3.; 1. /. r; 1. /. r; 0. ] (tr s "trace(S, <1,2,3>, <1,1,0>, N)");
          check "missed: both zero" [ 0.; 0.; 0.; 0.; 0.; 0. ] (tr s "trace(S, <10,10,10>, x, N)");
          check ~eps:1e-12 "a difference: the box's front face, not the cut sphere"
            [ 0.4; 0.8; -1.; 0.; 0.; -1. ]
            (tr "#declare S = difference { box { -1, 1 } sphere { 0, 1.2 } }" "trace(S, <0,0,-5>, <0.1,0.2,1>, N)");
          check "without the normal" [ 6.; -1.; 3. ]
            (Scn.vec ~prelude:"#declare P = plane { y, -1 } #declare I = trace(P, <0,5,0>, <1,-1,0.5>);" "I"));
      Alcotest.test_case "inside(O, P) is POV-Ray's inside test" `Quick (fun () ->
          check "inside" [ 1.; 0.; 0.; 1.; 1. ]
            (floats
               "#declare S = sphere { <1,2,3>, 2 } #declare D = difference { box { -1, 1 } sphere { 0, 1.2 } }\n\
                #declare P = plane { y, -1 }\n\
                sphere { 0, inside(S, <1,2,3>) } sphere { 0, inside(S, <5,5,5>) } sphere { 0, inside(D, 0) }\n\
                sphere { 0, inside(D, <0.95,0.95,0.95>) } sphere { 0, inside(P, <0,-2,0>) }"));
      Alcotest.test_case "trace in a macro: its normal goes into the caller's #local (tracevines)" `Quick (fun () ->
          (* FindTmp's shape: a macro whose body ends with 'Q;' read by a
             #local outside it: the name is bound where the #local stands *)
          check "macro value" [ 4.; 1. ]
            (floats
               "#declare S = sphere { 0, 1 }\n\
                #macro Hit(A) #local N = <0,0,0>; #local I = trace(S, A, -A, N); (I.x * 4) * N.x; #end\n\
                #macro Go() #local V = Hit(<5,0,0>) sphere { 0, V } #local W = 1; sphere { 0, W } #end\n\
                Go()"));
      Alcotest.test_case "trace of something that is not an object is a located error" `Quick (fun () ->
          let d = Scn.error "#declare F = 3;\n#declare I = trace(F, 0, x);" in
          Alcotest.(check string) "located at F" "<test>:2:20: error: trace needs an object: F is a float"
            (List.hd (String.split_on_char '\n' (Diag.to_string d))));
] )
