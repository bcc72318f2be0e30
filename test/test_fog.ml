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

(* POV-Ray's rainbow against its formula: a ray at [a] degrees from the
   direction reads the map at (a - angle + width / 2) / width, blended in by
   k = exp (-t / distance) (at least the colour's transmit); outside the
   band, or beyond half the arc angle from up, the light is unchanged;
   between the falloff angle and the arc angle it fades smoothly *)
let rainbow =
  Alcotest.test_case "rainbow: map index, distance blend, transmit floor, arc and falloff" `Quick (fun () ->
      let map c = [| (0., Pigment.solid c); (1., Pigment.solid c) |] in
      let bow ?(arc = 180.) ?(falloff = 180.) ?(distance = 10.) c =
        Rainbow.make ~angle:30. ~width:10. ~distance ~jitter:0. ~direction:(v 0. 0. 1.) ~up:(v 0. 1. 0.) ~arc ~falloff
          (Pigment.Map { pattern = Pattern.make (Pattern.Gradient (v 1. 0. 0.)); entries = map c; xform = Transform.identity })
      in
      (* a unit direction [deg] degrees from +z, turned [around] degrees from up about it *)
      let ray deg around =
        let r = deg *. Float.pi /. 180. and a = around *. Float.pi /. 180. in
        let m = Vec3.m () in
        Vec3.set m (Float.sin r *. Float.sin a) (Float.sin r *. Float.cos a) (Float.cos r);
        m
      in
      let through bows d t (r, g, b) =
        let c = Color.acc 0. in
        Color.acc_set c r g b;
        Rainbow.apply bows d t c;
        (c.ar, c.ag, c.ab)
      in
      let red = Color.rgbft 1. 0. 0. 0. 0. in
      let t = 10. *. Float.log 2. in
      close "on the band, half blended" (0.5 *. 0.2 +. 0.5, 0.5 *. 0.4, 0.5 *. 0.6)
        (through [ bow red ] (ray 30. 0.) t (0.2, 0.4, 0.6));
      close "before the band" (0.2, 0.4, 0.6) (through [ bow red ] (ray 24. 0.) t (0.2, 0.4, 0.6));
      close "past the band" (0.2, 0.4, 0.6) (through [ bow red ] (ray 35.5 0.) t (0.2, 0.4, 0.6));
      close "the sky: all rainbow" (1., 0., 0.) (through [ bow red ] (ray 33. 0.) Fog.missed (0.2, 0.4, 0.6));
      (* transmit 0.7 floors k: 0.7 of the light, 0.3 of the colour *)
      let veil = Color.rgbft 1. 0. 0. 0. 0.7 in
      close "transmit floor" (0.7 *. 0.2 +. 0.3, 0.7 *. 0.4, 0.7 *. 0.6)
        (through [ bow veil ] (ray 30. 0.) Fog.missed (0.2, 0.4, 0.6));
      (* filter 1: what passes is tinted by (1 - f) + f c, f = filter (1 - k) *)
      let glass = Color.rgbft 1. 0.5 0. 1. 0. in
      let k = 0.5 in
      let f = 1. *. (1. -. k) in
      close "filter tints" (k *. 0.2 *. ((1. -. f) +. f) +. 0.5, k *. 0.4 *. ((1. -. f) +. (f *. 0.5)) +. 0.25, k *. 0.6 *. (1. -. f))
        (through [ bow glass ] (ray 30. 0.) t (0.2, 0.4, 0.6));
      (* arc_angle 120, falloff_angle 60 (halves 60 and 30 degrees, in radians) *)
      let half x = x *. Float.pi /. 360. in
      let cut = bow ~arc:(half 120.) ~falloff:(half 60.) red in
      close "inside the falloff angle" (1., 0., 0.) (through [ cut ] (ray 30. 20.) Fog.missed (0.2, 0.4, 0.6));
      close "beyond the arc" (0.2, 0.4, 0.6) (through [ cut ] (ray 30. 70.) Fog.missed (0.2, 0.4, 0.6));
      (* half way through the falloff: fade 0.5 *)
      close "half faded" (0.5 *. 0.2 +. 0.5, 0.5 *. 0.4, 0.5 *. 0.6)
        (through [ cut ] (ray 30. 45.) Fog.missed (0.2, 0.4, 0.6));
      (* two bows at one ray: their results averaged *)
      let blue = Color.rgbft 0. 0. 1. 0. 0. in
      close "two bows averaged" (0.5, 0., 0.5) (through [ bow red; bow blue ] (ray 30. 0.) Fog.missed (0.2, 0.4, 0.6)))

(* POV-Ray 3.7's fog turbulence: noise_pov/fogturb.txt holds POV-Ray's
   render of fogturb.pov (a constant and a ground fog with turbulence,
   octaves, omega, lambda and turb_depth, over surfaces of ambient colour
   only), 32x24 without anti-aliasing, in 16-bit linear values
   (fogturb.sh); camlray's render of the same scene, pixel by pixel,
   within the 16-bit rounding (the turbulence moves pixels by up to
   5876 steps) *)
let pov_turbulence =
  Alcotest.test_case "fog turbulence: POV-Ray's render of fogturb.pov, pixel by pixel" `Quick (fun () ->
      let dir = if Sys.file_exists "../../../test/noise_pov" then "../../../test/noise_pov" else "noise_pov" in
      let text = In_channel.with_open_text (Filename.concat dir "fogturb.pov") In_channel.input_all in
      let img = Helpers.render_whitted ~width:32 ~height:24 text in
      let rows = In_channel.with_open_text (Filename.concat dir "fogturb.txt") In_channel.input_lines in
      if List.length rows <> 32 * 24 then Alcotest.failf "%d pixels" (List.length rows);
      List.iter
        (fun l ->
          match List.map int_of_string (String.split_on_char ' ' (String.trim l)) with
          | [ x; y; r; g; b ] ->
              let gr, gg, gb = Helpers.pixel img x y in
              let off want got = Float.abs ((got *. 65535.) -. float_of_int want) > 0.75 in
              if off r gr || off g gg || off b gb then
                Alcotest.failf "pixel (%d, %d): %.1f %.1f %.1f, POV-Ray %d %d %d" x y (gr *. 65535.) (gg *. 65535.)
                  (gb *. 65535.) r g b
          | _ -> Alcotest.fail "bad row")
        rows)

let tests = ("fog", units @ [ parsed; rainbow; pov_turbulence ])
