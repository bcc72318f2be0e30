(* Splines: declarations in the scene language and their values, against
   POV-Ray 3.7's printed values for the same splines. *)

let vec = Scn.vec
let check msg want got = Scn.check_floats ~eps:5e-5 msg want got

let pts = "-1, <0,1> 0, <1,0> 2, <4,4> 3, <9,1>"
let pts5 = pts ^ " 5, <2,2>"

let first2 = function a :: b :: _ -> [ a; b ] | l -> l

let tests =
  ( "spline",
    [
      Alcotest.test_case "linear, and natural by a second argument" `Quick (fun () ->
          let prelude = "#declare S = spline { linear_spline 0, <0,0,0> 1, <1,2,3>, 3, <3,0,1> }" in
          check "S(0.5)" [ 0.5; 1.; 1.5 ] (vec ~prelude "S(0.5)");
          check "S(2, natural)" [ 2.; 1.75; 3. ] (vec ~prelude "S(2, natural_spline)");
          check "member and arithmetic" [ 1.; 2.; 3. ] (vec ~prelude "S(0.5) * 2"));
      Alcotest.test_case "quadratic: inside and in the first segment" `Quick (fun () ->
          let prelude = "#declare Q = spline { quadratic_spline " ^ pts ^ " }" in
          check "Q(1)" [ 2.3333; 1. ] (first2 (vec ~prelude "Q(1)"));
          check "Q(-0.5)" [ 0.4583; 0.25 ] (first2 (vec ~prelude "Q(-0.5)")));
      Alcotest.test_case "cubic (Catmull-Rom) and its end rules" `Quick (fun () ->
          let prelude = "#declare C = spline { cubic_spline " ^ pts5 ^ " }" in
          check "C(1)" [ 2.; 2.25 ] (first2 (vec ~prelude "C(1)"));
          check "C(4.5)" [ 9.; 1. ] (first2 (vec ~prelude "C(4.5)"));
          check "C(-3)" [ 1.; 0. ] (first2 (vec ~prelude "C(-3)")));
      Alcotest.test_case "natural cubic, and clamping past the end" `Quick (fun () ->
          let prelude = "#declare N = spline { natural_spline " ^ pts5 ^ " }" in
          check "N(1)" [ 1.4556; 2.5242 ] (first2 (vec ~prelude "N(1)"));
          check "N(4)" [ 7.8548; 0.3065 ] (first2 (vec ~prelude "N(4)"));
          check "N(7)" [ 2.; 2. ] (first2 (vec ~prelude "N(7)")));
      Alcotest.test_case "float values give two terms; copying and extending a spline" `Quick (fun () ->
          check "F(0.25)" [ 1.5; 1.5; 0. ] (vec ~prelude:"#declare F = spline { 0, 1, 1, 3 }" "F(0.25)");
          check "S2(2)" [ 5.; 5.; 5. ]
            (vec
               ~prelude:"#declare S = spline { 0, <0,0,0> 1, <1,2,3> }\n#declare S2 = spline { S 2, <5,5,5> }"
               "S2(2)"));
      Alcotest.test_case "a spline function" `Quick (fun () ->
          check "F(0.5)" [ 1.; 2.; 3. ]
            (vec ~prelude:"#declare F = function { spline { linear_spline 0, <0,0,0> 1, <2,4,6> } }" "F(0.5)"));
      Alcotest.test_case "errors" `Quick (fun () ->
          Scn.check_message "#declare S = spline { }" "no points";
          Scn.check_message "#declare S = spline { 0, <1,2> }\nsphere { S(0, foo_spline), 1 }" "expected linear_spline");
    ] )
