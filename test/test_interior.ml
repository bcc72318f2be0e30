(* The interiors a ray is inside: relative indices and the lists of media
   past a surface, by POV-Ray's rule (entering or leaving is told by
   whether the ray is already inside the interior, not by the side of the
   surface). *)
open Camlray

let glass = { Interior.default with ior = 1.5 }
let water = { Interior.default with ior = 1.33 }

let relative () =
  let r = Interior.relative_ior in
  Alcotest.(check (float 1e-15)) "air into glass" (1. /. 1.5) (r glass []);
  Alcotest.(check (float 1e-15)) "glass out to air" 1.5 (r glass [ glass ]);
  Alcotest.(check (float 1e-15)) "glass into water inside it" (1.5 /. 1.33) (r water [ glass ]);
  Alcotest.(check (float 1e-15)) "water out into the glass around it" (1.33 /. 1.5) (r water [ water; glass ]);
  (* two children of a CSG share their parent's interior: where they
     overlap, the inner wall of the other child is left as glass to air *)
  Alcotest.(check (float 1e-15)) "a shared interior's inner wall" 1.5 (r glass [ glass ])

(* POV-Ray 3.7's ratio for fresnel reflections: the inverse of the
   refraction's, but leaving glass while inside something else (a hollow
   sphere around the camera) it is the innermost index over the glass's,
   1: no reflection from within *)
let fresnel () =
  let f = Interior.fresnel_ior and air = { Interior.default with ior = 1. } in
  Alcotest.(check (float 1e-15)) "air into glass" 1.5 (f glass []);
  Alcotest.(check (float 1e-15)) "glass out to air" (1. /. 1.5) (f glass [ glass ]);
  Alcotest.(check (float 1e-15)) "into glass inside a hollow sphere" 1.5 (f glass [ air ]);
  Alcotest.(check (float 1e-15)) "out of glass inside a hollow sphere" 1. (f glass [ glass; air ]);
  Alcotest.(check (float 1e-15)) "into water inside glass" (1.33 /. 1.5) (f water [ glass ]);
  Alcotest.(check (float 1e-15)) "out of water inside glass" 1. (f water [ water; glass ]);
  (* leaving glass from inside water entered later: water's over glass's *)
  Alcotest.(check (float 1e-15)) "out of glass from the water in it" (1.33 /. 1.5) (f glass [ water; glass ])

let beyond () =
  let b = Interior.beyond in
  let inside = b glass [] in
  Alcotest.(check int) "entered" 1 (List.length inside);
  Alcotest.(check bool) "glass first" true (List.hd inside == glass);
  Alcotest.(check bool) "entering again gives the same list (made once)" true (b glass [] == inside);
  Alcotest.(check bool) "left" true (b glass inside = []);
  let nested = b water inside in
  Alcotest.(check bool) "water inside glass" true (match nested with [ w; g ] -> w == water && g == glass | _ -> false);
  (* leaving an interior that is not the innermost takes it out where it is *)
  Alcotest.(check bool) "glass left from inside the water" true
    (match b glass nested with [ w ] -> w == water | _ -> false)

let fades_light () =
  Alcotest.(check bool) "no fade" false (Interior.fades_light glass);
  Alcotest.(check bool) "fade distance and power" true
    (Interior.fades_light { glass with fade_distance = 2.; fade_power = 2. });
  Alcotest.(check bool) "fade_power 0 fades what is seen, not light" false
    (Interior.fades_light { glass with fade_distance = 2.; fade_power = 0. })

(* Whose interior a ray is in (povray 3.7, 80x60, pixels where the
   first answer differs from the second): two nested clear spheres of
   ior 1.5 over a checker refract as separate solids when each has
   interior { I } of one declared I, or is a copy of one declared sphere;
   the parts of a union with one interior share it, and a ray crossing
   from the outer part into the inner leaves it. *)
let identity () =
  let scene spheres =
    "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n#declare I = interior { ior 1.5 }\n\
     #declare S = sphere { 0, 1 pigment { rgbf 1 } finish { ambient 0 diffuse 0 } interior { ior 1.5 } }\n\
     camera { location <0,0,-6> look_at 0 angle 40 }\n\
     plane { z, 3 pigment { checker rgb 1, rgb 0 scale 0.25 } finish { ambient 1 diffuse 0 } }\n" ^ spheres
  in
  let clear = "pigment { rgbf 1 } finish { ambient 0 diffuse 0 }" in
  let own =
    Printf.sprintf "sphere { 0, 2 %s interior { I } }\nsphere { <0.3,0.2,0>, 1 %s interior { I } }" clear clear
  and copies = "object { S scale 2 }\nobject { S translate <0.3,0.2,0> }"
  and shared = Printf.sprintf "union { sphere { 0, 2 %s } sphere { <0.3,0.2,0>, 1 %s } interior { I } }" clear clear in
  let at src (x, y) = (Scn.pixel ~w:80 ~h:60 ~x ~y (scene src)).Camlray.Color.r in
  List.iter
    (fun (p, separate, one) ->
      let name (x, y) what = Printf.sprintf "%s at %d,%d" what x y in
      Scn.close (name p "interior { I }") separate (at own p);
      Scn.close (name p "copies of a declared sphere") separate (at copies p);
      Scn.close (name p "one union's interior") one (at shared p))
    [ ((32, 20), 0., 1.); ((42, 20), 1., 0.); ((45, 20), 1., 0.) ]

let tests =
  ( "interior",
    [ Alcotest.test_case "relative index of refraction" `Quick relative;
      Alcotest.test_case "fresnel index ratio (POV-Ray's)" `Quick fresnel;
      Alcotest.test_case "media past a surface" `Quick beyond;
      Alcotest.test_case "which interiors fade shadow rays" `Quick fades_light;
      Alcotest.test_case "an object's own interior is its own; a union's is shared" `Quick identity ] )
