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

let tests =
  ( "interior",
    [ Alcotest.test_case "relative index of refraction" `Quick relative;
      Alcotest.test_case "fresnel index ratio (POV-Ray's)" `Quick fresnel;
      Alcotest.test_case "media past a surface" `Quick beyond;
      Alcotest.test_case "which interiors fade shadow rays" `Quick fades_light ] )
