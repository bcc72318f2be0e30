(* Area lights: POV-Ray's recursive averaging (pov-facts.md 5.3). *)
open Camlray

let avg n1 n2 blocked =
  let a = Light.area Vec3.unit_x Vec3.unit_z n1 n2 in
  (Light.average_area a (fun i j -> if List.mem (i, j) blocked then Color.black else Color.white)).r

let check msg expected actual = Scn.close msg expected actual

let averaging () =
  check "3x1, an end blocked" 0.75 (avg 3 1 [ (0, 0) ]);
  check "3x1, the middle blocked" 0.5 (avg 3 1 [ (1, 0) ]);
  check "5x1, an end blocked" 0.875 (avg 5 1 [ (0, 0) ]);
  check "2x1 is the plain mean" 0.5 (avg 2 1 [ (1, 0) ]);
  check "4x1 is the plain mean" 0.75 (avg 4 1 [ (2, 0) ]);
  check "2x2 is the plain mean" 0.75 (avg 2 2 [ (1, 1) ]);
  check "1x1" 0. (avg 1 1 [ (0, 0) ])

let adaptive () =
  let a = { (Light.area Vec3.unit_x Vec3.unit_z 5 5) with adaptive = 1 } in
  let f i j = if (i, j) = (1, 1) then Color.black else Color.white in
  check "adaptive 1 misses an interior sample" 1. (Light.average_area a f).r;
  let calls = ref 0 in
  let a = Light.area Vec3.unit_x Vec3.unit_z 9 9 in
  ignore (Light.average_area a (fun _ _ -> incr calls; Color.white));
  Alcotest.(check int) "each sample traced once" 81 !calls

let positions () =
  let l = { (Light.point (Vec3.make 0. 5. 0.) Color.white) with
            area = Some (Light.area (Vec3.make 2. 0. 0.) (Vec3.make 0. 0. 4.) 3 2) } in
  let a = Option.get l.area in
  let p i j = Light.sample_position l a Vec3.zero i j in
  let eq msg (e : Vec3.t) (v : Vec3.t) =
    Scn.close (msg ^ " x") e.x v.x; Scn.close (msg ^ " y") e.y v.y; Scn.close (msg ^ " z") e.z v.z
  in
  eq "corner" (Vec3.make (-1.) 5. (-2.)) (p 0 0);
  eq "middle of axis 1, end of axis 2" (Vec3.make 0. 5. 2.) (p 1 1)

(* a blocker covering one end sample of a 3x1 light: 0.75 of the light *)
let scene () =
  let c =
    Scn.pixel
      ("light_source { <0,0,-10>, rgb 1 area_light <4,0,0>, <0,0,0>, 3, 1 }\n\
        sphere { <-2,0,-9>, 0.2 pigment { rgb 1 } }\n\
        plane { z, 1 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }")
  in
  (* the light centre is head-on: diffuse 1; shadow average 0.75 *)
  Scn.gray "3x1 area light, an end blocked" 0.75 c

(* The shadows found at a point are kept until forgotten: the layers of
   a texture trace each shadow ray once. Told a lit point is the
   shadowed one's, the store answers with the kept shadow. *)
let kept_shadows () =
  let s =
    Scn.compile
      "light_source { <0,10,0>, rgb 1 }\n\
       sphere { <0,5,0>, 1 pigment { rgb 1 } }\n\
       plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }"
  in
  let pc = Pigment.out () in
  pc.r <- 1.;
  pc.g <- 1.;
  pc.b <- 1.;
  let k = { Direct.alpha = 1. } and n = Vec3.m () and d = Vec3.m () in
  Vec3.set n 0. 1. 0.;
  Vec3.set d 0. (-1.) 0.;
  let f = Finish.default and cache = Direct.shadows () in
  let at x =
    let p = Vec3.m () and out = Color.acc 0. in
    Vec3.set p x 0. 0.;
    Direct.lights s cache s.lights { f with diffuse = 1. } pc k p n d out;
    out.ar
  in
  check "under the sphere" 0. (at 0.);
  check "lit, but the kept shadow is the first point's" 0. (at 8.);
  Direct.forget cache;
  let lit = at 8. in
  if lit < 0.1 then Alcotest.failf "forgotten, the lit point is lit: %g" lit;
  (* straight under the light, and the kept shadow lets all through *)
  check "kept again: under the sphere, lit" 1. (at 0.)

(* light_group as compiled: the group's lights leave the global list and
   make a set of their own, which the group's surfaces name; with
   global_lights on the set starts with the global lights; every
   placement of a declared group is a set of its own (its lights moved
   with it) *)
let groups () =
  let s =
    Scn.compile
      "light_source { <0,10,0>, rgb 1 }\n\
       #declare G = light_group { light_source { <0,0,-3>, rgb <1,0,0> } sphere { 0, 1 } }\n\
       object { G translate -2*x }\n\
       object { G translate 2*x }\n\
       light_group { light_source { <0,5,0>, rgb <0,1,0> } box { -1, 1 } global_lights on translate 5*y }\n\
       sphere { 0, 1 }"
  in
  let n = Alcotest.(check int) in
  n "one global light" 1 (Array.length s.lights);
  n "the global set and three groups" 4 (Array.length s.light_sets);
  Alcotest.(check bool) "set 0 is the global lights" true (s.light_sets.(0) == s.lights);
  n "a group without global_lights: its own light" 1 (Array.length s.light_sets.(1));
  n "with global_lights on: the global light, then its own" 2 (Array.length s.light_sets.(3));
  Alcotest.(check bool) "global first" true (s.light_sets.(3).(0) == s.lights.(0));
  let pos k = (s.light_sets.(k).(0)).Light.position in
  Scn.close "the first placement's light moved with it" (-2.) (pos 1).x;
  Scn.close "the second's" 2. (pos 2).x;
  Scn.close "a transformed group's light" 10. (s.light_sets.(3).(1)).Light.position.y;
  let sets = Array.map (fun (o : Object.t) -> o.lights) s.objects in
  Alcotest.(check (list int)) "each surface names its set" [ 1; 2; 3; 0 ] (Array.to_list sets);
  n "every light once" 4 (Array.length (Scene.all_lights s))

let tests =
  ( "light",
    [
      Alcotest.test_case "recursive averaging" `Quick averaging;
      Alcotest.test_case "adaptive" `Quick adaptive;
      Alcotest.test_case "sample positions" `Quick positions;
      Alcotest.test_case "area light in a scene" `Quick scene;
      Alcotest.test_case "shadows kept per point" `Quick kept_shadows;
      Alcotest.test_case "light_group sets" `Quick groups;
    ] )
