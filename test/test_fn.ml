(* User-defined functions. Expected values printed by POV-Ray 3.7 for
   the same declarations. *)
open Camlray_lang

let f = Scn.float
let check = Scn.check_float ~eps:1e-9


(* Random splines as spline { ... } makes them: 1 to 8 entries (a
   parameter repeated replaces the value), float values (5 copies, 2
   terms) or vectors of 2 to 5 components; parameters on a grid of
   quarters (repeats, knots hit exactly) or anywhere *)
let same_bits a b = Int64.equal (Int64.bits_of_float a) (Int64.bits_of_float b)

let kinds = [ Spline.Linear; Spline.Quadratic; Spline.Cubic; Spline.Natural ]
let kind_name = function
  | Spline.Linear -> "linear_spline" | Quadratic -> "quadratic_spline" | Cubic -> "cubic_spline" | Natural -> "natural_spline"

let gen_par =
  QCheck.Gen.(oneof_weighted [ (2, map (fun i -> float_of_int i /. 4.) (int_range (-4) 12)); (1, float_range (-1.) 3.) ])

let gen_value =
  QCheck.Gen.(
    oneof_weighted
      [ (1, map (fun x -> (Array.make 5 x, 2)) (float_range (-5.) 5.));
        (3, int_range 2 5 >>= fun t -> map (fun v -> (v, t)) (array_size (return t) (float_range (-5.) 5.))) ])

let gen_spline =
  QCheck.Gen.(
    triple (oneof_list kinds) (list_size (int_range 1 8) (pair gen_par gen_value))
      (list_size (return 6) (oneof_weighted [ (4, gen_par); (1, float_range (-3.) 5.) ])))

let print_spline (kind, entries, ps) =
  Printf.sprintf "%s { %s } at %s" (kind_name kind)
    (String.concat " "
       (List.map
          (fun (p, (v, t)) ->
            Printf.sprintf "%h, <%s> (%d terms)" p (String.concat ", " (Array.to_list (Array.map (Printf.sprintf "%h") v))) t)
          entries))
    (String.concat " " (List.map (Printf.sprintf "%h") ps))

let make_spline kind entries =
  List.fold_left (fun s (p, (v, terms)) -> Spline.add s p ~terms v) (Spline.empty kind) entries

(* eval's component k, 0 past its length *)
let nth a k = if k < Array.length a then a.(k) else 0.

(* the in-place evaluation a spline function uses at render time, each
   component written into a slot between others, against Spline.eval;
   and the five components allocate nothing *)
let in_place_prop =
  QCheck.Test.make ~name:"Spline.component_into and Spline.value = Spline.eval, to the bit, allocating nothing"
    ~count:2000 (QCheck.make ~print:print_spline gen_spline)
    (fun (kind, entries, ps) ->
      let s = make_spline kind entries in
      let f = Spline.prepare s in
      List.for_all
        (fun p ->
          let want = Spline.eval s p in
          let src = [| 7.; p; 9. |] and dst = Array.make 9 42. in
          let before = Gc.minor_words () in
          for k = 0 to 4 do
            Spline.component_into f src 1 k dst (k + 2)
          done;
          let words = Gc.minor_words () -. before in
          let value = Spline.value f p in
          let bad k = QCheck.Test.fail_reportf "at %h, component %d: got %h, want %h" p k dst.(k + 2) (nth want k) in
          (words = 0. || QCheck.Test.fail_reportf "at %h: %g words" p words)
          && Spline.terms f = Array.length want
          && Array.length value = Array.length want
          && Array.for_all2 same_bits value want
          && List.for_all (fun k -> same_bits dst.(k + 2) (nth want k) || bad k) [ 0; 1; 2; 3; 4 ]
          && dst.(0) = 42. && dst.(1) = 42. && dst.(7) = 42. && dst.(8) = 42.
          && src = [| 7.; p; 9. |])
        ps)

(* a spline function's members in a function body (its render-time
   code: Fn.member_code), each one and gray, against Spline.eval *)
let member_prop =
  let members = [ ("x", 0); ("y", 1); ("z", 2); ("t", 3); ("transmit", 4); ("gray", -1) ] in
  QCheck.Test.make ~name:"S(t).member in a function body = Spline.eval's component, to the bit" ~count:300
    (QCheck.make ~print:print_spline gen_spline)
    (fun (kind, entries, ps) ->
      let s = make_spline kind entries in
      let sf = Fn.of_spline s in
      let resolve _ name = if name = "S" then Fnparse.Func sf else Fnparse.Unknown in
      List.for_all
        (fun (m, k) ->
          let toks = Lexer.tokenize ~file:"<fn>" (Printf.sprintf "S(a).%s" m) in
          let g = Fnparse.compile ~resolve ~params:[ "a" ] toks in
          List.for_all
            (fun p ->
              let e = Spline.eval s p in
              let want =
                if k < 0 then (0.297 *. nth e 0) +. (0.589 *. nth e 1) +. (0.114 *. nth e 2) else nth e k
              in
              let got = Fn.eval g [| p |] in
              same_bits got want || QCheck.Test.fail_reportf ".%s at %h: got %h, want %h" m p got want)
            ps)
        members)

(* POV-Ray 3.7's noise functions against POV-Ray itself: fn_pov/fn.txt
   was written by POV-Ray 3.7 running fn.pov beside it (each row a point,
   exactly as 17 decimals read back, then the values of the 26
   expressions of the array V its macro E declares: f_noise3d, f_snoise3d,
   f_noise_generator of generators 0 to 3 and of 4, 5.7, -1 (the low two
   bits of the integer part), f_ridge, f_ridged_mf (four declarations of
   internal(59), and functions.inc's called with other H and lacunarity
   after its first call: POV-Ray keeps the exponents of that first call),
   f_hetero_mf (fractional octaves and T), f_bozo, f_dents, f_spotted at
   20 lattice points, 20 in [-1, 1]^3 and 160 in [-20, 20]^3). The same
   declarations and macro, read from fn.pov, run here at the same points
   in the same order: all 5,200 values print as POV-Ray printed them. *)
let fn_pov_dir = if Sys.file_exists "../../../test/fn_pov" then "../../../test/fn_pov" else "fn_pov"

let pov_noise_functions () =
  let read name = In_channel.with_open_bin (Filename.concat fn_pov_dir name) In_channel.input_all in
  let script = read "fn.pov" in
  let prelude = String.sub script 0 (Str.search_forward (Str.regexp_string "#fopen") script 0) in
  let rows =
    List.filter_map
      (fun l -> if String.trim l = "" then None else Some (String.split_on_char ' ' (String.trim l)))
      (String.split_on_char '\n' (read "fn.txt"))
  in
  if List.length rows <> 200 then Alcotest.failf "%d rows" (List.length rows);
  let b = Buffer.create 65536 in
  Buffer.add_string b prelude;
  List.iter
    (function
      | x :: y :: z :: _ -> Printf.bprintf b "E(%s, %s, %s)\n#for (k, 0, 25) sphere { 0, V[k] } #end\n" x y z
      | _ -> Alcotest.fail "bad row")
    rows;
  let got = Array.of_list (Scn.floats (Buffer.contents b)) in
  if Array.length got <> 26 * 200 then Alcotest.failf "%d values" (Array.length got);
  (* every value printed as POV-Ray prints them (str(v, 0, 17), C's
     %.17f) is the same text: the same double but where 17 decimals
     cannot tell doubles apart (below 0.1) *)
  let bad = ref [] in
  List.iteri
    (fun r row ->
      match row with
      | x :: y :: z :: want ->
          List.iteri
            (fun k v ->
              let g = Printf.sprintf "%.17f" got.((26 * r) + k) in
              if g <> v then bad := Printf.sprintf "V[%d] of fn.pov at (%s, %s, %s): %s, POV-Ray %s" k x y z g v :: !bad)
            want
      | _ -> ())
    rows;
  if !bad <> [] then Alcotest.failf "%d values differ:\n%s" (List.length !bad) (String.concat "\n" (List.rev !bad))

(* f_noise3d while parsing takes the generator the global_settings read
   so far gave (else the #version's), 2 before any (POV-Ray 3.7 writes 0.68958521726421096
   before a noise_generator 3, 0.57330235388277662 after it and
   0.85531098758775803 after a noise_generator 1), and a
   scene parsed next starts again from 2 *)
let noise3d_generator () =
  let v = Scn.floats "#include \"functions.inc\"\n\
    sphere { 0, f_noise3d(0.3, 0.7, 1.1) }\n\
    global_settings { noise_generator 3 }\n\
    sphere { 0, f_noise3d(0.3, 0.7, 1.1) }\n\
    global_settings { noise_generator 1 }\n\
    sphere { 0, f_noise3d(0.3, 0.7, 1.1) }" in
  Scn.check_floats ~eps:0. "before, after 3, after 1"
    [ 0.68958521726421096; 0.57330235388277662; 0.85531098758775803 ] v;
  Scn.check_float ~eps:0. "the next scene" 0.68958521726421096 (f ~prelude:"#include \"functions.inc\"" "f_noise3d(0.3, 0.7, 1.1)");
  (* until global_settings name one, each #version sets it: 1 below 3.5
     (functions.inc's closing #version puts back 3.1 there), 2 from 3.5;
     one named stays (POV-Ray 3.7 writes these three values) *)
  let v = Scn.floats "#version 3.1;\n#include \"functions.inc\"\n\
    sphere { 0, f_noise3d(0.3, 0.7, 1.1) }\n\
    #version 3.7;\n\
    sphere { 0, f_noise3d(0.3, 0.7, 1.1) }\n\
    global_settings { noise_generator 3 }\n\
    #version 3.1;\n\
    sphere { 0, f_noise3d(0.3, 0.7, 1.1) }" in
  Scn.check_floats ~eps:0. "3.1, 3.7, 3 then 3.1" [ 0.85531098758775803; 0.68958521726421096; 0.57330235388277662 ] v;
  (* while rendering, the scene's: the last global_settings', else its
     version's (a #version 3.1 scene renders with the original noise, as
     POV-Ray 3.7 does: its picture of a bozo plane is that of
     noise_generator 1) *)
  let shade version setting =
    let s =
      Scn.compile ~raw:true
        (Printf.sprintf
           "#version %s;\nglobal_settings { assumed_gamma 1.0 %s }\n#include \"functions.inc\"\n\
            camera { location -z look_at 0 }\n\
            plane { z, 1 pigment { function { f_noise3d(0.3, 0.7, 1.1) } } finish { ambient 1 diffuse 0 } }"
           version setting)
    in
    (Camlray.Whitted.pixel s ~width:1 ~height:1 0 0).r
  in
  let g1 = shade "3.7" "noise_generator 1" and g2 = shade "3.7" "noise_generator 2" in
  if g1 = g2 then Alcotest.fail "generators 1 and 2 shade alike";
  Scn.check_float ~eps:0. "3.1, none: 1" g1 (shade "3.1" "");
  Scn.check_float ~eps:0. "3.7, none: 2" g2 (shade "3.7" "");
  Scn.check_float ~eps:0. "3.1, 2 named" g2 (shade "3.1" "noise_generator 2");
  Scn.check_float ~eps:1e-6 "the value" (Camlray.Noise.noise 1 0.3 0.7 1.1) g1

let tests =
  ( "fn",
    [
      Alcotest.test_case "default parameters x, y, z and declared constants" `Quick (fun () ->
          check "F(1,2,3)" 3.
            (f ~prelude:"#declare K = 2;\n#declare F = function { x*K + y*y - 3 }" "F(1, 2, 3)"));
      Alcotest.test_case "named parameters, calls, sum and prod" `Quick (fun () ->
          check "G(1,2)" 37.
            (f
               ~prelude:
                 "#declare F = function { x*2 + y*y - 3 }\n\
                  #declare G = function (a, b) { F(a, b, 0) + sum(i, 1, 4, i) + prod(i, 1, 4, i) }"
               "G(1, 2)");
          check "P(4)" 48. (f ~prelude:"#declare P = function(a) { prod(i, 1, a, i) + sum(j, 1, 3, j*a) }" "P(4)"));
      Alcotest.test_case "precedence: & binds tighter than |; unary minus; clock and pi" `Quick (fun () ->
          let prelude = "#declare H = function { select(x, -1, 0, 1) * 10 + (x < 2) + (1 | 1 & 0) + -x*2 + clock + pi }" in
          Scn.check_float ~eps:1e-3 "H(-1)" (-2.858) (f ~prelude "H(-1, 0, 0)");
          Scn.check_float ~eps:1e-3 "H(3)" 8.142 (f ~prelude "H(3, 0, 0)"));
      Alcotest.test_case "u and v name x and y" `Quick (fun () ->
          check "U" 3. (f ~prelude:"#declare U = function { u + v }" "U(1, 2, 3)"));
      Alcotest.test_case "a constant is read when the function is defined" `Quick (fun () ->
          check "K frozen" 2.
            (f ~prelude:"#declare K = 2; #declare F = function { K } #declare K = 5;" "F(0, 0, 0)"));
      Alcotest.test_case "math.inc functions" `Quick (fun () ->
          let prelude = "#include \"math.inc\"" in
          if Sys.file_exists Parse.pov_include_dir then begin
            check "sind(30)" 0.5 (f ~prelude "sind(30)");
            check "clip" 1. (f ~prelude "clip(5, 0, 1)");
            check "even(4)" 1. (f ~prelude "even(4)");
            check "odd(4)" 0. (f ~prelude "odd(4)");
            check "sgn" (-1.) (f ~prelude "sgn(-3)");
            check "adj_range" 3. (f ~prelude "adj_range(0.5, 2, 4)");
            check "max3" 5. (f ~prelude "max3(1, 5, 2)");
            check "atan2d" 45. (f ~prelude "atan2d(1, 1)")
          end);
      Alcotest.test_case "transform functions: vtransform of transforms.inc" `Quick (fun () ->
          if Sys.file_exists Parse.pov_include_dir then begin
            let prelude = "#include \"transforms.inc\"" in
            Scn.check_floats ~eps:1e-9 "Reorient_Trans" [ -2.; 1.; 3. ]
              (Scn.vec ~prelude "vtransform(<1,2,3>, Reorient_Trans(x, y))");
            Scn.check_floats ~eps:1e-9 "Axis_Rotate_Trans" [ 0.; 0.; -1. ]
              (Scn.vec ~prelude "vtransform(<1,0,0>, Axis_Rotate_Trans(<0,1,0>, 90))")
          end);
      Alcotest.test_case "Fn.eval3 evaluates from OCaml" `Quick (fun () ->
          let toks = Lexer.tokenize ~file:"<fn>" "x*x + y*y + z*z - 1" in
          let fn = Fnparse.compile ~resolve:(fun _ _ -> Fnparse.Unknown) ~params:[ "x"; "y"; "z" ] toks in
          let g = Fn.eval3 fn in
          check "eval3" 2. (g 1. 1. 1.);
          check "eval" (-1.) (Fn.eval fn [| 0.; 0.; 0. |]));
      Alcotest.test_case "errors: POV-Ray's limits of the function syntax" `Quick (fun () ->
          Scn.check_message "#declare V = <1,2,3>; #declare F = function { V }" "is a vector";
          Scn.check_message "#declare F = function { x ? 1 : 2 }" "expected an operator";
          Scn.check_message "#declare F = function { Nope(x) }" "undefined identifier Nope";
          Scn.check_message "#declare F = function(a) { a } sphere {0, F(1, 2)}" "takes 1 argument";
          Scn.check_message "#declare F = function { }" "cannot be empty";
          Scn.check_message "#declare F = function(a, a) { a }" "listed twice");
      Alcotest.test_case "pigment functions: channels in scene expressions and functions" `Quick (fun () ->
          (* POV-Ray 3.7 prints 0.25,0.5,0.75,0,0 for C and 4.7925 for G *)
          let prelude =
            "#declare PF = function { pigment { gradient x color_map { [0 rgb <0,0.5,1>] [1 rgb <1,0.5,0>] } } }\n\
             #declare G = function { PF(x,y,z).x + PF(x,y,z).gray*10 }\n\
             #declare C = PF(0.25, 0, 0);"
          in
          check "C.red" 0.25 (f ~prelude "C.red");
          check "C.blue" 0.75 (f ~prelude "C.blue");
          check "C.transmit" 0. (f ~prelude "C.transmit");
          check "G" 4.7925 (f ~prelude "G(0.25, 0, 0)");
          let prelude = "#declare PF = function { pigment { rgbft <0.1, 0.2, 0.3, 0.4, 0.5> } }" in
          check "filter" 0.4 (f ~prelude:(prelude ^ " #declare H = function { PF(x,y,z).filter }") "H(0,0,0)");
          check "t" 0.4 (f ~prelude:(prelude ^ " #declare H = function { PF(x,y,z).t }") "H(0,0,0)");
          check "transmit" 0.5 (f ~prelude:(prelude ^ " #declare H = function { PF(x,y,z).transmit }") "H(0,0,0)"));
      Alcotest.test_case "members of transform and spline functions in functions" `Quick (fun () ->
          let prelude =
            "#declare T = function { transform { scale <2, 3, 4> translate x } }\n\
             #declare S = function { spline { linear_spline 0, <0, 0, 0>, 1, <2, 4, 6> } }\n\
             #declare F = function { T(x, y, z).y + T(x, y, z).x * 10 + S(x).z * 100 }"
          in
          (* T(0.5, 1, 1) = <2, 3, 4>; S(0.5) = <1, 2, 3> *)
          check "F" 323. (f ~prelude "F(0.5, 1, 1)");
          check "T(...).y in the scene" 3. (f ~prelude "T(0.5, 1, 1).y"));
      Alcotest.test_case "errors: members" `Quick (fun () ->
          let pf = "#declare PF = function { pigment { rgb 1 } }\n" in
          Scn.check_message (pf ^ "#declare G = function { PF(x, y, z).w }") ".w is not a member";
          Scn.check_message (pf ^ "#declare G = function { PF(x, y, z) }") "vector function";
          Scn.check_message (pf ^ "#declare G = function { PF(x, y).red }") "takes 3 arguments";
          Scn.check_message "#declare F = function { x } #declare G = function { F(x, y, z).x }"
            "returns a float";
          Scn.check_message "#declare G = function { (x + y).x }" "applies only to a call";
          Scn.check_message "#declare T = function { transform { scale 2 } } #declare G = function { T(x, y, z).filter }"
            "3 components";
          Scn.check_message "#declare P = function(a) { pigment { rgb 1 } }" "no parameter list");
      Alcotest.test_case "internal functions declare but cannot be called" `Quick (fun () ->
          Scn.check_message "#declare F = function { internal(3) } sphere {0, F(1,2,3)}" "internal function 3");
      Alcotest.test_case "f_sphere, f_torus, f_rounded_box, f_superellipsoid = POV-Ray's values" `Quick (fun () ->
          (* values POV-Ray 3.7 printed for these calls *)
          let prelude = "#include \"functions.inc\"" in
          let p = "-1.560188485207, 0.277405011998, -0.667199350583" in
          let f e = Scn.float ~prelude e in
          Scn.close ~eps:1e-11 "f_sphere" 1.019388444614 (f ("f_sphere(" ^ p ^ ", 0.7)"));
          Scn.close ~eps:1e-11 "f_torus" 0.358178277131 (f ("f_torus(" ^ p ^ ", 1.1, 0.3)"));
          Scn.close ~eps:1e-11 "f_rounded_box" 0.578357629346 (f ("f_rounded_box(" ^ p ^ ", 0.2, 1, 0.5, 0.7)"));
          Scn.close ~eps:1e-11 "f_superellipsoid" (-1.227777511482) (f ("f_superellipsoid(" ^ p ^ ", 0.5, 2)"));
          Scn.close ~eps:1e-8 "f_superellipsoid 0.7, 1.3" (-0.826646919)
            (Scn.float ~prelude "f_superellipsoid(-1.560188485207, 0.277405011998, -0.667199350583, 0.7, 1.3)");
          Scn.check_message (prelude ^ " #declare G = function { f_torus(x, y, z, 1) }") "takes 5 arguments");
      Alcotest.test_case "f_r, f_th, f_ph = POV-Ray's values" `Quick (fun () ->
          let prelude = "#include \"functions.inc\"" in
          List.iter
            (fun (p, r, th, ph) ->
              Scn.close ~eps:1e-9 ("f_r " ^ p) r (Scn.float ~prelude ("f_r(" ^ p ^ ")"));
              Scn.close ~eps:1e-9 ("f_th " ^ p) th (Scn.float ~prelude ("f_th(" ^ p ^ ")"));
              Scn.close ~eps:1e-9 ("f_ph " ^ p) ph (Scn.float ~prelude ("f_ph(" ^ p ^ ")")))
            [ ("0.3, 0.2, 0.1", 0.374165739, 1.249045772, 1.006853685);
              ("-1.7, 0.5, -0.2", 1.783255450, -1.687905071, 1.286600030);
              ("0.2, -1.2, 0.8", 1.456021978, 0.244978663, 2.539519733);
              ("-0.5, 0, -0.5", 0.707106781, -2.356194490, 1.570796327) ]);
      Alcotest.test_case "function { pattern { ... } } = POV-Ray's values" `Quick (fun () ->
          let pts = [ (0.3, 0.2, 0.1); (1.7, 0.5, -0.2); (-0.9, 1.2, 0.8); (0.05, -0.35, 0.6) ] in
          List.iter
            (fun (src, expected) ->
              List.iter2
                (fun (x, y, z) e ->
                  Scn.close ~eps:1e-6 (Printf.sprintf "%s at (%g, %g, %g)" src x y z) e
                    (Scn.float ~prelude:(Printf.sprintf "#declare F = function { pattern { %s } }" src)
                       (Printf.sprintf "F(%g, %g, %g)" x y z)))
                pts expected)
            [
              ("gradient x", [ 0.300000; 0.700000; 0.100000; 0.050000 ]);
              ("checker", [ 0.000000; 0.000000; 0.000000; 1.000000 ]);
              ("onion scale 0.5", [ 0.748331; 0.566511; 0.400000; 0.392839 ]);
              ("leopard scale 0.2", [ 0.597215; 0.034285; 0.000383; 0.039397 ]);
              ("gradient y sine_wave frequency 2", [ 0.793893; 0.500000; 0.793893; 0.975528 ]);
              ("boxed", [ 0.700000; 0.000000; 0.000000; 0.400000 ]);
              ("spiral1 3", [ 0.982591; 0.917128; 0.214418; 0.042588 ]);
              ("gradient x warp { repeat x*0.7 flip x }", [ 0.300000; 0.300000; 0.500000; 0.050000 ]);
              ("hexagon", [ 0.000000; 1.000000; 2.000000; 0.000000 ]);
              ("mandel 20", [ 1.000000; 0.000000; 0.050000; 1.000000 ]);
              ("brick", [ 1.000000; 1.000000; 1.000000; 0.000000 ]);
            ]);
      Alcotest.test_case "noise functions = POV-Ray's values at 200 points" `Quick pov_noise_functions;
      Alcotest.test_case "f_noise3d: the generator global_settings gave so far while parsing" `Quick noise3d_generator;
    ] @ List.map QCheck_alcotest.to_alcotest [ in_place_prop; member_prop ] )
