(* POV-Ray's photons in whitted mode: the words as read, the photon
   map's searches against brute force, and the light of caustics
   against values measured with POV-Ray 3.7 (16x16 renders, +FN16,
   gamma 1, the mean of the pixels). *)
open Camlray

let settings src =
  match (Scn.compile src).settings.photons with Some p -> p | None -> Alcotest.fail "no photons in the settings"

let words () =
  let p = settings "global_settings { photons { } }" in
  Scn.close "spacing" 1. p.spacing;
  Alcotest.(check (list int)) "count, gather" [ 0; 20; 100 ] [ p.count; p.gather_min; p.gather_max ];
  Scn.check_floats "jitter, autostop, expand, radius" [ 0.4; 0.5; 0.2; 0.; 1. ]
    [ p.jitter; p.autostop; p.expand_tolerance; p.radius; p.radius_mult ];
  Alcotest.(check int) "no media photons" 0 p.media_steps;
  Alcotest.(check int) "expand count" 35 p.expand_min;
  let p =
    settings
      "global_settings { photons { spacing 0.02 gather 10, 50 jitter 0 max_trace_level 9 adc_bailout 0.01 autostop 0 \
       expand_thresholds 0.3, 20 radius 0.5, 2, 0.1, 3 media 100, 2 } }"
  in
  Alcotest.(check int) "media steps" 100 p.media_steps;
  Scn.check_floats "media's factor and radius" [ 2.; 0.1; 3. ] [ p.media_factor; p.media_radius; p.media_mult ];
  Alcotest.(check (list int)) "ints" [ 10; 50; 9; 20 ] [ p.gather_min; p.gather_max; p.max_trace_level; p.expand_min ];
  Scn.check_floats "floats" [ 0.02; 0.; 0.01; 0.; 0.3; 0.5; 2. ]
    [ p.spacing; p.jitter; p.adc_bailout; p.autostop; p.expand_tolerance; p.radius; p.radius_mult ];
  Alcotest.(check int) "count" 5000 (settings "global_settings { photons { count 5000 } }").count;
  (* an object's and a light's words; a union's pushed down to its
     children, over theirs *)
  let s =
    Scn.compile
      "light_source { <0, 9, 0>, 1 photons { refraction on reflection off area_light } }\n\
       union { sphere { 0, 1 photons { reflection on collect off } } sphere { x, 1 }\n\
      \  photons { target 0.5 refraction on reflection off } }\n\
       sphere { 3*x, 1 photons { pass_through } }"
  in
  let l = s.lights.(0).photons in
  Alcotest.(check (list int)) "light's switches" [ 1; -1 ] [ l.refraction; l.reflection ];
  Alcotest.(check bool) "area_light" true l.area_light;
  let flags = Array.to_list (Array.map (fun (o : Object.t) -> o.photon) s.objects) in
  (match flags with
  | [ a; b; c ] ->
      Scn.check_floats "targets" [ 0.5; 0.5; 0. ] [ a.target; b.target; c.target ];
      Alcotest.(check (list int)) "the union's words win" [ 1; -1; 1; -1 ] [ a.refraction; a.reflection; b.refraction; b.reflection ];
      Alcotest.(check (list bool)) "collect" [ false; true; true ] [ a.collect; b.collect; c.collect ];
      Alcotest.(check bool) "pass_through" true c.pass_through
  | _ -> Alcotest.fail "three objects expected")

let errors () =
  Scn.check_message "global_settings { photons { gather 30, 20 } }" "the minimum is above the maximum";
  Scn.check_message "global_settings { photons { spacing 0 } }" "spacing 0: it must be positive";
  Scn.check_message "global_settings { photons { target } }" "not a global_settings word";
  Scn.check_message "sphere { 0, 1 photons { area_light } }" "an object's photons block takes";
  Scn.check_message "light_source { 0, 1 photons { target } }" "a light's photons block takes";
  Scn.check_message "sphere { 0, 1 photons { refraction } }" "refraction needs on or off"

(* merged and per-surface rules *)
let rules () =
  let f ?(refraction = 0) ?(reflection = 0) ?(target = 0.) () = { Photon.none with refraction; reflection; target } in
  Alcotest.(check bool) "target on, light unsaid: shot" true (Photon.shoots (f ~refraction:1 ()) ~light:(f ()));
  Alcotest.(check bool) "nothing said: not shot" false (Photon.shoots (f ()) ~light:(f ()));
  Alcotest.(check bool) "light off wins" false (Photon.shoots (f ~refraction:1 ()) ~light:(f ~refraction:(-1) ()));
  Alcotest.(check bool) "light on refracts at unsaid surfaces" true (Photon.refracts (f ()) ~light:(f ~refraction:1 ()));
  Alcotest.(check bool) "surface off" false (Photon.refracts (f ~refraction:(-1) ()) ~light:(f ~refraction:1 ()));
  Alcotest.(check bool) "refracting target blocks shadows" true
    (Photon.blocks_shadow (f ~target:1. ~refraction:1 ()) ~light:(f ()));
  Alcotest.(check bool) "reflecting target does not" false
    (Photon.blocks_shadow (f ~target:1. ~reflection:1 ()) ~light:(f ()))

(* a map of random photons *)
let map_of ?(gmin = 3) ?(gmax = 8) pts =
  let st = Photon.store () in
  List.iter (fun (x, y, z) -> Photon.add st x y z ~r:1. ~g:1. ~b:1. 0. 1. 0.) pts;
  let s = { (Photon.default_settings ()) with gather_min = gmin; gather_max = gmax; radius = 0.3 } in
  Photon.build s st

let cloud = QCheck.(list_size Gen.(1 -- 300) (triple (float_range (-1.) 1.) (float_range (-1.) 1.) (float_range (-1.) 1.)))

(* the k nearest within a radius, by brute force: their distances *)
let brute pts (x, y, z) r k flat =
  List.map
    (fun (a, b, c) ->
      let vx = a -. x and vy = b -. y and vz = c -. z in
      let d2 = (vx *. vx) +. (vy *. vy) +. (vz *. vz) in
      if flat then d2 *. (1. +. (16. *. Float.abs vy)) else d2)
    pts
  |> List.filter (fun d -> d < r *. r)
  |> List.sort compare
  |> List.filteri (fun i _ -> i < k)

let found_d2 m q (x, y, z) flat =
  List.init (Photon.found q) (fun j ->
      let i = Photon.index q j in
      let vx = Photon.position m i 0 -. x and vy = Photon.position m i 1 -. y and vz = Photon.position m i 2 -. z in
      let d2 = (vx *. vx) +. (vy *. vy) +. (vz *. vz) in
      if flat then d2 *. (1. +. (16. *. Float.abs vy)) else d2)
  |> List.sort compare

let close_lists a b = List.length a = List.length b && List.for_all2 (fun x y -> Float.abs (x -. y) < 1e-12) a b

let nearest_is_brute =
  QCheck.Test.make ~count:200 ~name:"kd-tree nearest = brute force"
    QCheck.(pair cloud (triple (float_range (-1.) 1.) (float_range (-1.) 1.) (float_range (-1.) 1.)))
    (fun (pts, ((x, y, z) as c)) ->
      let m = map_of pts in
      let q = Photon.query () in
      let n = Photon.nearest m q x y z ~radius:0.5 in
      n = List.length (brute pts c 0.5 8 false) && close_lists (found_d2 m q c false) (brute pts c 0.5 8 false))

(* the flattened gather (normal +y) within the map's radius *)
let gather_is_brute =
  QCheck.Test.make ~count:200 ~name:"flattened gather = brute force" QCheck.(pair cloud (pair (float_range (-1.) 1.) (float_range (-1.) 1.)))
    (fun (pts, (x, z)) ->
      let m = map_of ~gmin:0 pts in
      let q = Photon.query () in
      let p = Vec3.m () and n = Vec3.m () in
      Vec3.set p x 0. z;
      Vec3.set n 0. 1. 0.;
      Photon.gather m q p n;
      let want = brute pts (x, 0., z) (Photon.radius m) 8 true in
      let area_ok =
        (* the search radius when it held at most 8, else the farthest kept *)
        let all = brute pts (x, 0., z) (Photon.radius m) max_int true in
        let r2 = if List.length all > 8 then List.nth want 7 else Photon.radius m ** 2. in
        Float.abs (Photon.area q -. (Float.pi *. r2)) < 1e-9
      in
      close_lists (found_d2 m q (x, 0., z) true) want && area_ok)

(* Caustics against POV-Ray: a floor (diffuse, ambient 0) under a clear
   sphere target, lit from above, seen from straight above *)
let floor ?(collect = "") ?(sphere = "pigment { rgbf 1 } finish { ambient 0 diffuse 0 } interior { ior 1 }") ?(light = "")
    ?(extra = "") ~at ~size ~diffuse () =
  let x, z = at in
  Printf.sprintf
    "#version 3.7;\n\
     global_settings { assumed_gamma 1.0 photons { spacing 0.01 } }\n\
     camera { orthographic location <%g, 1, %g> look_at <%g, 0, %g> right x*%g up z*%g sky z }\n\
     light_source { <0, 10, 0>, rgb 1 %s }\n\
     plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse %g } %s }\n\
     sphere { <0, 3, 0>, 1 %s photons { target refraction on } }\n%s"
    x z x z size size light diffuse collect sphere extra

let mean_render ?(domains = 1) src =
  let s = Scn.compile ~raw:true src in
  Caustics.prepare ?par:(if domains > 1 then Some (Render.pulled ~domains) else None) s;
  let img = Render.image ~domains ~width:16 ~height:16 (Whitted.pixel s ~width:16 ~height:16) in
  let sum = ref 0. in
  for y = 0 to 15 do
    for x = 0 to 15 do
      sum := !sum +. Image.get_r img x y
    done
  done;
  (!sum /. 256., img)

let near msg ~rel want got =
  if Float.abs (got -. want) > rel *. want then Alcotest.failf "%s: %.4f, POV-Ray %.4f (more than %.0f%% apart)" msg got want (100. *. rel)

let caustics () =
  (* a clear target of index 1: its photons bring the light its full
     shadow keeps away (POV-Ray: 0.5031; the directly lit floor 0.4642
     four units aside) *)
  near "through a clear target" ~rel:0.02 0.5031 (fst (mean_render (floor ~at:(0., 0.) ~size:0.4 ~diffuse:0.5 ())));
  (* a glass ball's caustic, at its centre and aside *)
  let glass = "pigment { rgbf 1 } finish { ambient 0 diffuse 0 } interior { ior 1.5 }" in
  near "a glass ball's caustic" ~rel:0.02 0.4681 (fst (mean_render (floor ~sphere:glass ~at:(0., 0.) ~size:0.4 ~diffuse:0.1 ())));
  near "its edge" ~rel:0.02 0.1877 (fst (mean_render (floor ~sphere:glass ~at:(0.3, 0.3) ~size:0.2 ~diffuse:0.1 ())));
  (* the same ball under other lights *)
  List.iter
    (fun (what, light, want) ->
      near what ~rel:0.02 want (fst (mean_render (floor ~sphere:glass ~light ~at:(0., 0.) ~size:0.4 ~diffuse:0.1 ()))))
    [ ("a spotlight", "spotlight point_at <0, 0, 0> radius 4 falloff 8 tightness 5", 0.4665);
      ("a parallel light", "parallel point_at <0, 0, 0>", 0.0918);
      ("a fading light", "fade_distance 4 fade_power 2", 0.1287);
      ("an area light shooting from its samples", "area_light x, z, 3, 3 photons { area_light }", 0.3371) ];
  (* a clear slab under the ball that says nothing of photons stops
     them (stored on it): a dark floor; no_image, photons from the light
     do not see it (POV-Ray: 0, and 0.4681 as without it) *)
  let slab flag =
    floor ~sphere:glass ~extra:("box { <-2, 1.5, -2>, <2, 1.6, 2> pigment { rgbf 1 } interior { ior 1.5 } " ^ flag ^ " }")
      ~at:(0., 0.) ~size:0.4 ~diffuse:0.1 ()
  in
  near "a slab in the way" ~rel:0. 0. (fst (mean_render (slab "")));
  near "a no_image slab" ~rel:0.02 0.4681 (fst (mean_render (slab "no_image")));
  (* a floor that does not collect: the glass casts its usual filtered
     shadow (all the light through) *)
  near "collect off" ~rel:1e-3 0.1
    (fst (mean_render (floor ~collect:"photons { collect off }" ~sphere:glass ~at:(0., 0.) ~size:0.4 ~diffuse:0.1 ())));
  (* a mirror wall's reflection on the floor, over its direct light
     (POV-Ray: 0.3103, 0.1816 without photons) *)
  let wall photons =
    Printf.sprintf
      "#version 3.7;\n\
       global_settings { assumed_gamma 1.0 photons { spacing 0.01 } }\n\
       camera { orthographic location <0.3, 1, 0> look_at <0.3, 0, 0> right x*0.4 up z*0.4 sky z }\n\
       light_source { <-2, 5, 0>, rgb 1 }\n\
       plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0.2 } }\n\
       box { <1, 0.01, -2>, <1.1, 3, 2> pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 0.8 } %s }"
      photons
  in
  near "a mirror's caustic" ~rel:0.02 0.3103 (fst (mean_render (wall "photons { target reflection on }")));
  near "no target, no caustic" ~rel:1e-3 0.1816 (fst (mean_render (wall "")))

(* media photons: a hollow clear box of scattering media, a target lit
   from above, seen from the front; its samples' shadow rays are
   blocked (the box refracts its light's photons) and its light comes as
   media photons (POV-Ray: 0.6051, 0.6000 lit directly without photons;
   with extinction 1, 0.4763 and 0.3514) *)
let media_photons () =
  let box ?(collect = "") ~photons ~ext () =
    Printf.sprintf
      "#version 3.7;\n\
       global_settings { assumed_gamma 1 max_trace_level 10 %s }\n\
       camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x*0.4 up y*0.4 }\n\
       light_source { <0, 30, 0> color rgb 1 photons { refraction on reflection off } }\n\
       box { <-1, -1, -1>, <1, 1, 1> hollow pigment { rgbf 1 } photons { target }\n\
      \  interior { media { scattering { 1, rgb 0.3 extinction %d } %s method 3 intervals 1 samples 10, 10 } } }"
      (if photons then "photons { spacing 0.03 media 100, 2 }" else "")
      ext collect
  in
  let s = Scn.compile ~raw:true (box ~photons:true ~ext:0 ()) in
  Caustics.prepare s;
  (match s.settings.photons with
  | Some { state = { media_map = Some m; _ }; _ } -> Alcotest.(check bool) "media photons stored" true (Photon.size m > 1000)
  | _ -> Alcotest.fail "no media photon map");
  near "lit by media photons" ~rel:0.02 0.6051 (fst (mean_render (box ~photons:true ~ext:0 ())));
  near "lit directly" ~rel:1e-3 0.6 (fst (mean_render (box ~photons:false ~ext:0 ())));
  near "media photons, extinction 1" ~rel:0.02 0.4763 (fst (mean_render (box ~photons:true ~ext:1 ())));
  near "lit directly, extinction 1" ~rel:1e-3 0.3514 (fst (mean_render (box ~photons:false ~ext:1 ())));
  (* a medium that says collect off: no photons left in it, its samples
     lit directly (POV-Ray 0.6000) *)
  near "collect off" ~rel:1e-3 0.6 (fst (mean_render (box ~collect:"collect off" ~photons:true ~ext:0 ())))

(* the photons are shot once, the same whatever the domains shooting
   and rendering *)
let domains () =
  let src = floor ~sphere:"pigment { rgbf 1 } interior { ior 1.5 }" ~at:(0.2, 0.) ~size:0.6 ~diffuse:0.3 () in
  let _, a = mean_render ~domains:1 src and _, b = mean_render ~domains:2 src in
  let same = ref true in
  for y = 0 to 15 do
    for x = 0 to 15 do
      if Image.get_r a x y <> Image.get_r b x y then same := false
    done
  done;
  Alcotest.(check bool) "1 and 2 domains" true !same

let tests =
  ( "photons",
    [
      Alcotest.test_case "words and defaults" `Quick words;
      Alcotest.test_case "errors" `Quick errors;
      Alcotest.test_case "refraction and reflection rules" `Quick rules;
      QCheck_alcotest.to_alcotest nearest_is_brute;
      QCheck_alcotest.to_alcotest gather_is_brute;
      Alcotest.test_case "caustics against POV-Ray" `Quick caustics;
      Alcotest.test_case "media photons against POV-Ray" `Quick media_photons;
      Alcotest.test_case "same on any domains" `Quick domains;
    ] )
