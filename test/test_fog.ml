(* POV-Ray's fog against its formulas: the constant fog's exp (-d / D), the
   transmit floor and filter tint, the ground fog's mean density (atan
   integral), fogs combined, the sky through a ground fog. *)
open Camlray

let v = Vec3.make

let fog ?(kind = Fog.Constant) ?(filter = 0.) ?(transmit = 0.) distance (r, g, b) =
  { Fog.kind; distance; color = Color.rgbft r g b filter transmit; turbulence = None }

(* the colour [c] seen at distance [t] (units of [d]) from [o] *)
let seen fogs o d t (r, g, b) =
  let m x = let a = Vec3.m () in Vec3.load a x; a in
  let c = Color.acc 0. in
  Color.acc_set c r g b;
  Fog.apply fogs (m o) (m d) t c;
  (c.ar, c.ag, c.ab)

let close name (er, eg, eb) (r, g, b) =
  let ok a b = Float.abs (a -. b) <= 1e-12 *. (1. +. Float.abs a) in
  if not (ok er r && ok eg g && ok eb b) then
    Alcotest.failf "%s: expected (%.15g, %.15g, %.15g), got (%.15g, %.15g, %.15g)" name er eg eb r g b

let units =
  [
    Alcotest.test_case "constant fog: exp (-d / D) of the colour, the rest the fog's" `Quick (fun () ->
        (* a direction of length 2: t = 2.5 is 5 units *)
        let a = exp (-0.5) in
        close "blend" (a *. 0.2 +. (1. -. a) *. 0.9, a *. 0.4 +. (1. -. a) *. 0.8, a *. 0.6 +. (1. -. a) *. 0.7)
          (seen [ fog 10. (0.9, 0.8, 0.7) ] (v 1. 2. 3.) (v 0. 0. 2.) 2.5 (0.2, 0.4, 0.6)));
    Alcotest.test_case "transmit floors the attenuation; filter tints what passes" `Quick (fun () ->
        (* a ray that meets nothing crosses 2e10 units: all fog but the floor *)
        let a = 0.6 and f = 0.5 and fc = (1., 0.5, 0.) in
        let r, g, b = fc in
        let tint c = a *. ((1. -. f) +. (f *. c)) in
        close "floor and filter"
          (tint r *. 0.3 +. ((1. -. a) *. r), tint g *. 0.3 +. ((1. -. a) *. g), tint b *. 0.3 +. ((1. -. a) *. b))
          (seen [ fog ~filter:f ~transmit:a 50. fc ] Vec3.zero (v 0. 0. 1.) infinity (0.3, 0.3, 0.3)));
    Alcotest.test_case "two fogs: attenuations multiply, colours add" `Quick (fun () ->
        let a1 = exp (-0.4) and a2 = exp (-0.2) in
        let exp_c c f1 f2 = (a1 *. a2 *. c) +. ((1. -. a1) *. f1) +. ((1. -. a2) *. f2) in
        close "two" (exp_c 0.5 0.1 0.2, exp_c 0.5 0.3 0.4, exp_c 0.5 0.5 0.6)
          (seen [ fog 10. (0.1, 0.3, 0.5); fog 20. (0.2, 0.4, 0.6) ] Vec3.zero (v 1. 0. 0.) 4. (0.5, 0.5, 0.5)));
    Alcotest.test_case "a fog of zero distance is no fog" `Quick (fun () ->
        close "none" (0.5, 0.25, 0.125) (seen [ fog 0. (1., 1., 1.) ] Vec3.zero (v 1. 0. 0.) 4. (0.5, 0.25, 0.125)));
    Alcotest.test_case "ground fog: mean density 1 / (1 + h^2) along a level ray, 1 below the offset" `Quick (fun () ->
        let ground = Fog.Ground { offset = 1.; alt = 2.; up = Vec3.unit_y } in
        (* at y = 3: one altitude above the offset, density 1/2 *)
        let a = exp (-.(8. *. 0.5) /. 10.) in
        close "level" (a *. 0.2 +. (1. -. a), a *. 0.2 +. (1. -. a), a *. 0.2 +. (1. -. a))
          (seen [ fog ~kind:ground 10. (1., 1., 1.) ] (v 0. 3. 0.) (v 1. 0. 0.) 8. (0.2, 0.2, 0.2));
        let a = exp (-8. /. 10.) in
        close "below" (a *. 0.2, a *. 0.2, a *. 0.2)
          (seen [ fog ~kind:ground 10. (0., 0., 0.) ] (v 0. 0.5 0.) (v 0. 0. 1.) 8. (0.2, 0.2, 0.2)));
    Alcotest.test_case "ground fog: straight up, mean density atan(H)/H" `Quick (fun () ->
        let ground = Fog.Ground { offset = 0.; alt = 1.; up = Vec3.unit_y } in
        (* from the offset up 3 altitudes: density atan 3 / 3 over 3 units *)
        let a = exp (-.Float.atan 3. /. 5.) in
        close "up 3" (a, a, a) (seen [ fog ~kind:ground 5. (0., 0., 0.) ] Vec3.zero (v 0. 1. 0.) 3. (1., 1., 1.));
        (* the sky straight up: 2e10 units, all of the atan's pi/2 *)
        let a = exp (-.Float.atan 2e10 /. 5.) in
        close "sky" (a, a, a) (seen [ fog ~kind:ground 5. (0., 0., 0.) ] Vec3.zero (v 0. 1. 0.) infinity (1., 1., 1.)));
  ]

(* through the scene language: the fog block's items and errors *)
let parsed =
  Alcotest.test_case "fog blocks read as POV-Ray reads them" `Quick (fun () ->
      let scene src = Geom_gen.scene_of_string src in
      let s = scene "fog { rgb <0.1, 0.2, 0.3> 40 } fog { fog_type 2 distance 5 fog_alt 2 fog_offset 1 up z rotate 90*x color rgbt <1, 1, 1, 0.25> turbulence 0.5 octaves 3 }" in
      match s.fog with
      | [ a; b ] ->
          Alcotest.(check (float 0.)) "a bare number is the distance" 40. a.distance;
          Alcotest.(check (float 0.)) "a bare vector is the colour" 0.2 a.color.c.g;
          Alcotest.(check (float 0.)) "transmit" 0.25 b.color.transmit;
          (match b.kind with
           | Fog.Ground { offset; alt; up } ->
               Alcotest.(check (float 0.)) "offset" 1. offset;
               Alcotest.(check (float 0.)) "alt" 2. alt;
               (* z turned 90 degrees about x (left-handed): -y *)
               Alcotest.(check (float 1e-12)) "up turned" (-1.) up.y
           | Fog.Constant -> Alcotest.fail "fog_type 2 is a ground fog");
          (match b.turbulence with
           | Some u -> Alcotest.(check int) "octaves" 3 u.octaves;
               Alcotest.(check (float 0.)) "turb_depth default" 0.5 u.depth
           | None -> Alcotest.fail "turbulence")
      | l -> Alcotest.failf "%d fogs" (List.length l))

let tests = ("fog", units @ [ parsed ])
