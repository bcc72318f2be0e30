(* Expression values: operators, built-in functions, strings, random
   streams. Expected values were printed by POV-Ray 3.7 (#debug of str(x,
   0, 9)) for the same expressions. *)

let pov_floats =
  [ ("mod(-7,3)", -1.); ("int(-2.5)", -2.); ("log(100)", 2.); ("(1 | 1 & 0)", 0.);
    ("div(-7,2)", -3.); ("floor(-2.5)", -3.); ("ceil(-2.5)", -2.); ("select(-1, 10, 20)", 10.);
    ("select(0, 10, 20, 30)", 20.); ("min(3, 1, 2)", 1.); ("max(3, 1, 5, 2)", 5.);
    ("atan2(1, -1)", 2.356194490); ("degrees(pi)", 180.); ("radians(180)", 3.141592654);
    ("vlength(<3,4,0>)", 5.); ("vdot(<1,2,3>,<4,5,6>)", 32.); ("pow(2, 10)", 1024.);
    ("abs(-3)", 3.); ("sqrt(2)", 1.414213562); ("exp(1)", 2.718281828); ("ln(10)", 2.302585093);
    ("(1 = 1 + 1e-11)", 1.); ("(1 != 1 + 1e-9)", 1.); ("(3 < 2 + 2)", 1.); ("!0", 1.); ("!3", 0.);
    ("-2 * -3", 6.); ("7 / 2", 3.5); ("(2 ? 5 : 6)", 5.); ("(0 ? 5 : 6)", 6.); ("<1,2,3>.y", 2.);
    ("(<1,2,3> + 2).z", 5.); ("(<1,2,3> * <2,2,2>).x", 2.); ("vcross(x, y).z", 1.);
    ("vrotate(x, <0,0,90>).y", 1.); ("vaxis_rotate(x, y, 90).z", -1.); ("vnormalize(<3,0,4>).x", 0.6);
    ("strlen(\"hello\")", 5.); ("val(\"3.25\")", 3.25); ("asc(\"A\")", 65.);
    ("strcmp(\"abc\", \"abd\")", -1.); ("true + yes + on + off", 3.); ("mod(7.5, 2)", 1.5);
    ("mod(-7.5, 2)", -1.5); ("div(7,-2)", -3.); ("sinh(1)", 1.175201194); ("acosh(2)", 1.316957897);
    ("bitwise_and(12, 10)", 8.); ("bitwise_or(12,10)", 14.); ("bitwise_xor(12,10)", 6.);
    ("int(2.9999)", 2.) ]

(* Colour channels: POV-Ray prints them through single precision (0.4 ->
   0.400000006); camlray keeps doubles, hence the tolerance. *)
let pov_colours =
  [ ("C1.green", 0.4); ("C2.filter", 0.4); ("C3.transmit", 0.4); ("C4.gray", 0.5); ("C5.red", 0.3);
    ("C5.green", 0.2); ("C6.red", 0.214041144); ("C6.green", 0.033104762); ("C7.transmit", 0.5) ]

let colour_prelude =
  "global_settings { assumed_gamma 1 }\n\
   #declare C1 = rgb <0.2,0.4,0.6>; #declare C2 = rgbf <0.1,0.2,0.3,0.4>;\n\
   #declare C3 = rgbt <0.1,0.2,0.3,0.4>; #declare C4 = rgb 0.5;\n\
   #declare C5 = color red 0.3 green 0.2; #declare C6 = srgb <0.5, 0.2, 1>;\n\
   #declare C7 = color 0.5;"

let pov_strings =
  [ ("str(3.14159, 0, 2)", "3.14"); ("str(3.14159, 8, 3)", "   3.142"); ("str(-3.5, -8, 2)", "-0003.50");
    ("str(7, 0, 0)", "7"); ("str(2.5, 0, -1)", "2.500000"); ("concat(\"a\", \"b\", \"c\")", "abc");
    ("chr(65)", "A"); ("substr(\"abcdef\", 2, 3)", "bcd"); ("strupr(\"aBc\")", "ABC");
    ("strlwr(\"aBc\")", "abc"); ("vstr(2, <1,2>, \":\", 0, 1)", "1.0:2.0");
    ("vstr(3, <1.5,2,3>, \", \", 5, 2)", " 1.50,  2.00,  3.00") ]

(* vturbulence(lambda, omega, octaves, V) against POV-Ray itself:
   fn_pov/vt.txt was written by POV-Ray 3.7 running vt.pov beside it
   (each row a point, exactly as 17 decimals read back, then the three
   components of vturbulence there for seven parameter sets: octaves 6, 3,
   10, 2.9 (truncated), 25 (kept to 10), 0.4 (raised to 1) and 1; lambda
   and omega that single precision rounds). Every component prints as
   POV-Ray printed it (C's %.17f). *)
let vt_sets = [ (2., 0.5, 6.); (2.3, 0.6, 3.); (1.7, 0.35, 10.); (3., 0.7, 2.9); (2., 0.5, 25.); (2., 0.5, 0.4); (2.1, 0.45, 1.) ]

let fn_pov_dir = if Sys.file_exists "../../../test/fn_pov" then "../../../test/fn_pov" else "fn_pov"

let vturbulence () =
  let rows =
    List.filter_map
      (fun l -> if String.trim l = "" then None else Some (String.split_on_char ' ' (String.trim l)))
      (String.split_on_char '\n' (In_channel.with_open_bin (Filename.concat fn_pov_dir "vt.txt") In_channel.input_all))
  in
  if List.length rows <> 100 then Alcotest.failf "%d rows" (List.length rows);
  let b = Buffer.create 16384 in
  List.iter
    (function
      | x :: y :: z :: _ ->
          List.iter
            (fun (l, o, n) -> Printf.bprintf b "sphere { vturbulence(%.17g, %.17g, %.17g, <%s, %s, %s>), 1 }\n" l o n x y z)
            vt_sets
      | _ -> Alcotest.fail "bad row")
    rows;
  let got = Array.of_list (List.map fst (Scn.spheres (Scn.parse (Buffer.contents b)))) in
  let sets = List.length vt_sets in
  if Array.length got <> sets * 100 then Alcotest.failf "%d values" (Array.length got);
  List.iteri
    (fun r row ->
      match row with
      | x :: y :: z :: want ->
          List.iteri
            (fun k w ->
              let (c : Camlray.Vec3.t) = got.((sets * r) + (k / 3)) in
              let g = Printf.sprintf "%.17f" (match k mod 3 with 0 -> c.x | 1 -> c.y | _ -> c.z) in
              if g <> w then
                Alcotest.failf "parameter set %d, component %d at <%s, %s, %s>: %s, POV-Ray %s" (k / 3) (k mod 3) x y z g w)
            want
      | _ -> ())
    rows;
  Scn.check_floats ~eps:0. "a float promotes to a vector" (Scn.vec "vturbulence(2, 0.5, 1, <0.4, 0.4, 0.4>)")
    (Scn.vec "vturbulence(2, 0.5, 1, 0.4)");
  Scn.check_message "#declare V = vturbulence(2, 0.5, <1, 2, 3>);" "vturbulence expects 4 arguments";
  Scn.check_message "#declare F = function { vturbulence(2, 0.5, 1, x) }" "cannot be used in a function"

(* A string expression's value, read back through #error. *)
let string_value e =
  let d = Scn.error (Printf.sprintf "#declare S = %s;\n#error concat(\"[\", S, \"]\")\n" e) in
  let m = d.Camlray_lang.Diag.msg in
  match (String.index_opt m '[', String.rindex_opt m ']') with
  | Some i, Some j -> String.sub m (i + 1) (j - i - 1)
  | _ -> Alcotest.failf "no value in %S" m

let tests =
  ( "value",
    List.map
      (fun (e, want) ->
        Alcotest.test_case ("float " ^ e) `Quick (fun () -> Scn.check_float ~eps:1e-8 e want (Scn.float e)))
      pov_floats
    @ List.map
        (fun (e, want) ->
          Alcotest.test_case ("colour " ^ e) `Quick (fun () ->
              Scn.check_float ~eps:1e-7 e want (Scn.float ~prelude:colour_prelude e)))
        pov_colours
    @ List.map
        (fun (e, want) ->
          Alcotest.test_case ("string " ^ e) `Quick (fun () ->
              Alcotest.(check string) e want (string_value e)))
        pov_strings
    @ [
        Alcotest.test_case "rand streams draw POV-Ray's numbers" `Quick (fun () ->
            (* POV-Ray 3.7: seed(0) then rand x5; seed(42) x3; seed(-1) *)
            Scn.check_floats ~eps:1e-11 "seed(0)"
              [ 0.000002874294; 0.466563684509; 0.249070228834; 0.965876042136; 0.636504033030 ]
              (Scn.floats
                 "#declare S = seed(0);\n#for (I, 1, 5) sphere { 0, rand(S) } #end");
            Scn.check_floats ~eps:1e-9 "seed(42), seed(-1)"
              [ 0.723582911; 0.329979260; 0.755761670; 0.578012874 ]
              (Scn.floats
                 "#declare S = seed(42); sphere {0, rand(S)} sphere {0, rand(S)} sphere {0, rand(S)}\n\
                  #declare T = seed(-1); sphere {0, rand(T)}"));
        Alcotest.test_case "seed() numbers streams from 0; streams are independent" `Quick (fun () ->
            Scn.check_floats "ids" [ 0.; 1.; 2. ]
              (Scn.floats "sphere {0, seed(5)} sphere {0, seed(5)} sphere {0, seed(7)}");
            (* interleaving draws from another stream does not change a stream *)
            Scn.check_floats ~eps:0. "same sequence"
              (Scn.floats "#declare A = seed(3); sphere {0, rand(A)} sphere {0, rand(A)}")
              (Scn.floats
                 "#declare A = seed(3); #declare B = seed(3); sphere {0, rand(A)} #local Z = rand(B);\n\
                  sphere {0, rand(A)}"));
        Alcotest.test_case "rand of an unknown stream is an error" `Quick (fun () ->
            Scn.check_message "sphere { 0, rand(3) }" "no such random stream");
        Alcotest.test_case "a float promotes to a vector" `Quick (fun () ->
            Scn.check_floats "<1,2,3>+2" [ 3.; 4.; 5. ] (Scn.vec "<1,2,3> + 2");
            Scn.check_floats "2 * x" [ 2.; 0.; 0. ] (Scn.vec "2 * x"));
        Alcotest.test_case "strings do not add" `Quick (fun () ->
            Scn.check_message "#declare S = \"a\" + 1;" "does not apply to strings");
        Alcotest.test_case "too many vector components" `Quick (fun () ->
            Scn.check_message "sphere { <1,2,3,4,5,6>, 1 }" "2 to 5 components");
        Alcotest.test_case "vturbulence = POV-Ray's values at 100 points" `Quick vturbulence;
        Alcotest.test_case "vstr needs 2 to 5 components" `Quick (fun () ->
            Scn.check_message "#declare S = vstr(7, x, \",\", 0, 1);" "2 to 5");
      ] )
