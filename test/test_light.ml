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
  eq "middle of axis 1, end of axis 2" (Vec3.make 0. 5. 2.) (p 1 1);
  (* the offsets the area keeps are [offset]'s, to the bit, on each axis *)
  List.iter
    (fun (n1, n2) ->
      let a = Light.area Vec3.unit_x Vec3.unit_z n1 n2 in
      let check name n t =
        Alcotest.(check int) (name ^ " length") (max 1 n) (Float.Array.length t);
        Float.Array.iteri
          (fun i v -> if Int64.bits_of_float v <> Int64.bits_of_float (Light.offset (max 1 n) i) then
              Alcotest.failf "%s: offset %d of %d" name i n) t
      in
      check "axis 1" n1 a.offsets1;
      check "axis 2" n2 a.offsets2)
    [ (1, 1); (2, 7); (5, 5); (17, 3); (0, 4) ]

(* POV-Ray's orient (trace.cpp): with d the unit direction from the lit
   point to the light, the axes along d x z (d x y within 0.01 of +-z)
   and d x (the first), both as long as the first axis; a parallel light's
   d runs from its point_at to it, wherever the point. POV-Ray's circular
   map: offsets plus 0.001, out to the larger one's distance. *)
let orient_rules () =
  let eq msg (e : Vec3.t) (v : Vec3.t) =
    Scn.close ~eps:1e-12 (msg ^ " x") e.x v.x; Scn.close ~eps:1e-12 (msg ^ " y") e.y v.y;
    Scn.close ~eps:1e-12 (msg ^ " z") e.z v.z
  in
  (* axis 2 of another length: only axis 1's (2) counts *)
  let a = { (Light.area (Vec3.make 2. 0. 0.) (Vec3.make 0. 5. 0.) 3 3) with orient = true } in
  let l = { (Light.point Vec3.zero Color.white) with area = Some a } in
  (* from below: d = +y, d x z = +x, d x x = -z *)
  eq "d along y" (Vec3.make 1. 0. (-1.)) (Light.position_at l a (Vec3.make 0. (-10.) 0.) 0.5 0.5);
  (* from in front: d = +z, within 0.01 of z: d x y = -x, d x -x = -y *)
  eq "d along z" (Vec3.make (-1.) (-1.) 0.) (Light.position_at l a (Vec3.make 0. 0. (-10.)) 0.5 0.5);
  (* |d.z| = 0.995: still the d x y case; 0.98: the d x z case *)
  let dz z = Vec3.make (Float.sqrt (1. -. (z *. z))) 0. z in
  let from z = Vec3.neg (Vec3.scale 10. (dz z)) in
  let d = dz 0.995 in
  let e1 = Vec3.normalize (Vec3.cross d Vec3.unit_y) in
  eq "0.995: d x y" (Vec3.scale 1. e1) (Light.position_at l a (from 0.995) 0.5 0.);
  let d = dz 0.98 in
  let e1 = Vec3.normalize (Vec3.cross d Vec3.unit_z) in
  eq "0.98: d x z" (Vec3.scale 1. e1) (Light.position_at l a (from 0.98) 0.5 0.);
  (* a parallel light: d from its point_at (0, -1, 0) to it, +y *)
  let par = { l with kind = Light.Parallel { point_at = Vec3.make 0. (-1.) 0. } } in
  eq "parallel" (Vec3.make 1. 0. (-1.)) (Light.position_at par a (Vec3.make 5. (-3.) 7.) 0.5 0.5);
  (* circular, not oriented: axes x and y *)
  let c = { (Light.area Vec3.unit_x Vec3.unit_y 5 5) with circular = true } in
  let lc = { l with area = Some c } in
  let disc u v =
    let ju = u +. 0.001 and jv = v +. 0.001 in
    let k = Float.max (Float.abs ju) (Float.abs jv) /. Float.sqrt ((ju *. ju) +. (jv *. jv)) in
    Vec3.make (ju *. k) (jv *. k) 0.
  in
  eq "circular (1, 3/4)" (disc 0.5 0.25) (Light.position_at lc c Vec3.zero 0.5 0.25);
  eq "circular corner" (disc (-0.5) 0.5) (Light.position_at lc c Vec3.zero (-0.5) 0.5);
  eq "circular centre" (disc 0. 0.) (Light.position_at lc c Vec3.zero 0. 0.);
  (* the corner (0.501, 0.251) lands at the distance 0.501, on its own direction *)
  let p = Light.position_at lc c Vec3.zero 0.5 0.25 in
  Scn.close ~eps:1e-12 "on the disc" 0.501 (Vec3.length p);
  Scn.close ~eps:1e-12 "its direction" (0.251 /. 0.501) (p.y /. p.x)

(* POV-Ray's parser: orient makes an area light circular, unless one of
   its sizes is 1; circular with a size of 1 is an error *)
let orient_circular () =
  let area src =
    match (Helpers.compile_string ("#version 3.7;\nlight_source { 0, rgb 1 " ^ src ^ " }\n")).lights with
    | [| { area = Some a; _ } |] -> a
    | _ -> Alcotest.fail "expected one area light"
  in
  Alcotest.(check bool) "orient: circular" true (area "area_light x, y, 3, 3 orient").circular;
  Alcotest.(check bool) "orient, 3x1: not circular" false (area "area_light x, y, 3, 1 orient").circular;
  Alcotest.(check bool) "no orient: as written" false (area "area_light x, y, 3, 3").circular;
  match Camlray_lang.Parse.string "#version 3.7;\nlight_source { 0, rgb 1 area_light x, y, 3, 1 circular }\n" with
  | Error _ -> Alcotest.fail "parse error"
  | Ok sdl -> (
      match Camlray_lang.Compile.scene sdl with
      | Ok _ -> Alcotest.fail "circular 3x1 accepted"
      | Error d ->
          let msg = Camlray_lang.Diag.to_string d in
          if not (Str.string_match (Str.regexp ".*:2:1: error: a circular area light must have more than one sample") msg 0)
          then Alcotest.failf "message %S" msg)

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

(* area_illumination by POV-Ray 3.7's rule (trace.cpp,
   ComputeFullAreaDiffuseLight): the shadow as for any area light, times
   the mean of what every sample of the grid gives as a point light. A
   3x1 light 2 above the lit point, its samples at x = -1, 0, 1: cosines
   2/sqrt 5, 1, 2/sqrt 5, mean (1 + 4/sqrt 5)/3; a small sphere hiding
   the x = 1 sample alone: the shadow average 0.75, as without
   area_illumination, times the same mean (each sample shadowed on its
   own instead gave (2/sqrt 5 + 1)/4 + 1/4 = 0.7236). A spotlight's
   samples keep the light's axis: a sample beside the light, straight
   above the point, sees it on the axis. *)
let area_illumination () =
  let at blocker =
    let s =
      Scn.compile
        ("light_source { <0,2,0>, rgb 1 area_light <2,0,0>, <0,0,0>, 3, 1 area_illumination on }\n" ^ blocker
       ^ "plane { y, -1 pigment { rgb 1 } }")
    in
    let pc = Pigment.out () in
    pc.r <- 1.;
    pc.g <- 1.;
    pc.b <- 1.;
    let k = { Direct.alpha = 1. } and n = Vec3.m () and d = Vec3.m () and p = Vec3.m () and out = Color.acc 0. in
    Vec3.set n 0. 1. 0.;
    Vec3.set d 0. (-1.) 0.;
    Direct.lights s (Direct.shadows ()) s.lights { Finish.default with diffuse = 1. } pc k p n d out;
    out.ar
  in
  let mean = (1. +. (4. /. Float.sqrt 5.)) /. 3. in
  check "unshadowed: the samples' mean cosine" mean (at "");
  check "one end hidden: 0.75 of it" (0.75 *. mean) (at "sphere { <0.5,1,0>, 0.1 }\n");
  let spot =
    {
      (Light.point Vec3.zero Color.white) with
      kind = Light.spot ~point_at:(Vec3.make 0. (-1.) 0.) ~radius:10. ~falloff:20. ~tightness:0.;
    }
  in
  let p = Vec3.m () in
  Vec3.set p 1. (-1.) 0.;
  check "spot sample, the light's axis" 1. (Light.attenuation_shifted spot 1. 0. 0. p);
  check "spot sample, its own axis to point_at: outside" 0. (Light.attenuation_at spot 1. 0. 0. p)

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

(* POV-Ray's cylindrical light (lightsource.cpp, Attenuate_Light), by
   hand: with x = 1 - d/falloff, x^tightness, times between radius and
   falloff the step (3 - 2s) s^2, s = x / (1 - radius/falloff) *)
let cylinder_formula () =
  let f ~r ~fo ~t d = Light.cylinder_factor ~radius:r ~falloff:fo ~tightness:t d in
  (* the defaults: radius 0.75, falloff 1, tightness 0 *)
  check "on the axis" 1. (f ~r:0.75 ~fo:1. ~t:0. 0.);
  check "inside radius" 1. (f ~r:0.75 ~fo:1. ~t:0. 0.5);
  (* d 0.9: x 0.1, s 0.1/0.25 = 0.4, (3 - 0.8) 0.16 *)
  check "between radius and falloff" 0.352 (f ~r:0.75 ~fo:1. ~t:0. 0.9);
  check "at falloff" 0. (f ~r:0.75 ~fo:1. ~t:0. 1.);
  check "past falloff" 0. (f ~r:0.75 ~fo:1. ~t:0. 1.5);
  (* radius 1 falloff 2 tightness 2, d 1.5: x 0.25, x^2 0.0625, s 0.5 -> 0.5 *)
  check "tightness and step" 0.03125 (f ~r:1. ~fo:2. ~t:2. 1.5);
  (* inside radius only the power: d 0.5, x 0.75 *)
  check "tightness inside radius" 0.5625 (f ~r:1. ~fo:2. ~t:2. 0.5);
  check "radius 0: no step" 0.75 (f ~r:0. ~fo:2. ~t:1. 0.5);
  (* radius past falloff: never between them *)
  check "radius beyond falloff" 0.25 (f ~r:3. ~fo:2. ~t:1. 1.5);
  check "falloff 0 lights nothing" 0. (f ~r:0. ~fo:0. ~t:0. 0.)

let cylinder_light ?(r = 0.75) ?(fo = 1.) ?(t = 0.) pos at =
  { (Light.point pos Color.white) with kind = Light.Cylinder { point_at = at; radius = r; falloff = fo; tightness = t } }

(* a light at <0,5,0> toward the origin: the distance from the y axis
   decides, not from the light; nothing at or behind its plane; the
   direction is the axis, the distance the one to the light's plane *)
let cylinder_light_at () =
  let l = cylinder_light (Vec3.make 0. 5. 0.) Vec3.zero in
  let att x y z = Light.attenuation l (Vec3.make x y z) in
  check "0.9 from the axis" 0.352 (att 0.9 0. 0.);
  check "the same far below" 0.352 (att 0. (-100.) 0.9);
  check "just in front of the plane" 0.352 (att 0.9 4.999 0.);
  check "on the plane" 0. (att 0.9 5. 0.);
  check "behind" 0. (att 0. 6. 0.);
  let d, dist = Light.direction_to l (Vec3.make 3. 1. 7.) in
  check "direction: up the axis" 1. d.y;
  check "direction x" 0. d.x;
  check "distance to the light's plane" 4. dist;
  let _, dist = Light.direction_to l (Vec3.make 0. 6. 0.) in
  check "behind: negative" (-1.) dist;
  (* fade by the distance along the axis: 2 / (1 + (4/2)^2) *)
  let l = { l with fade_distance = 2.; fade_power = 2. } in
  check "fade along the axis" 0.4 (Light.attenuation l (Vec3.make 0.3 1. 0.));
  (* a tilted axis: 0.9 across it *)
  let l = cylinder_light Vec3.zero (Vec3.make 1. 1. 0.) in
  let k = 0.9 /. Float.sqrt 2. in
  check "tilted axis" 0.352 (Light.attenuation l (Vec3.make (2. +. k) (2. -. k) 0.));
  check "no axis: nothing" 0. (Light.attenuation (cylinder_light Vec3.zero Vec3.zero) (Vec3.make 0. 0. 1.))

(* the rays are parallel: a point moved along the axis keeps its light;
   the factor is that of its distance from the axis, 0 behind the light *)
let cylinder_parallel =
  let open QCheck in
  let v = Gen.(map3 Vec3.make (float_range (-5.) 5.) (float_range (-5.) 5.) (float_range (-5.) 5.)) in
  Test.make ~name:"cylinder light: parallel rays, the factor of the distance from the axis" ~count:2000
    (make Gen.(quad v v (pair v (float_range 0. 20.)) (triple (float_range 0. 2.) (float_range 0.1 3.) (float_range 0. 4.))))
    (fun (pos, at, (p, s), (r, fo, t)) ->
      assume (Vec3.dist pos at > 0.1);
      let l = cylinder_light ~r ~fo ~t pos at in
      let a = Vec3.normalize (Vec3.sub at pos) in
      let v = Vec3.sub p pos in
      let k = Vec3.dot v a in
      let d = Vec3.length (Vec3.sub v (Vec3.scale k a)) in
      let expected = if k > 1e-9 then Light.cylinder_factor ~radius:r ~falloff:fo ~tightness:t d else 0. in
      let near x y = Float.abs (x -. y) <= 1e-9 in
      (Float.abs k < 1e-6 || near (Light.attenuation l p) expected)
      && (k < 1e-6 || near (Light.attenuation l (Vec3.add p (Vec3.scale s a))) (Light.attenuation l p)))

(* light_source { cylinder } in a scene: a plane facing the light head on
   (diffuse 1), its pixel at 0.9 from the axis: 0.352; a sphere on the
   axis casts its shadow down the beam, not toward the light *)
let cylinder_scene () =
  let scene ~extra x =
    Scn.pixel
      (Printf.sprintf
         "camera { orthographic location <%g, 0, -10> look_at <%g, 0, 0> right 0.01*x up 0.01*y }
          light_source { <0, 0, -5>, rgb 1 cylinder point_at <0, 0, 0> }
          plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
%s" x x extra)
  in
  Scn.gray "0.9 from the axis" 0.352 (scene ~extra:"" 0.9);
  Scn.gray "on the axis" 1. (scene ~extra:"" 0.);
  Scn.gray "past falloff" 0. (scene ~extra:"" 1.2);
  (* a ball beside the axis at 0.5: its shadow falls straight down the
     beam, at x = 0.5 (a point light at <0,0,-5> would cast it at 0.8) *)
  let ball = "sphere { <0.5, 0, -3>, 0.1 pigment { rgb 1 } no_image }" in
  Scn.gray "parallel shadow" 0. (scene ~extra:ball 0.5);
  (* 0.8 from the axis: x 0.2, s 0.8, (3 - 1.6) 0.64 *)
  Scn.gray "none where a point light's would be" 0.896 (scene ~extra:ball 0.8)

(* POV-Ray's light types as its parser switches them: shadowless makes
   a point light (keeping the parallel flag a cylinder set), a type
   keyword casts shadows again; a parallel spotlight is a parallel light *)
let light_types () =
  let kind text =
    let s = Scn.compile text in
    let l = s.lights.(0) in
    ( (match l.kind with
      | Light.Point -> "point" | Light.Spot _ -> "spot" | Light.Parallel _ -> "parallel"
      | Light.Cylinder { radius; falloff; tightness; _ } -> Printf.sprintf "cylinder %g %g %g" radius falloff tightness),
      l.shadowless )
  in
  let is msg (k, sh) text = Alcotest.(check (pair string bool)) msg (k, sh) (kind text) in
  is "cylinder: POV-Ray's defaults" ("cylinder 0.75 1 0", false) "light_source { 0, 1 cylinder }";
  is "written values" ("cylinder 2 3 4", false)
    "light_source { 0, 1 cylinder point_at -y radius 2 falloff 3 tightness 4 }";
  is "cylinder shadowless: a parallel light" ("parallel", true) "light_source { 0, 1 cylinder point_at -y shadowless }";
  is "shadowless cylinder: shadows" ("cylinder 0.75 1 0", false) "light_source { 0, 1 shadowless cylinder }";
  is "cylinder resets a spotlight's values" ("cylinder 0.75 1 0", false)
    "light_source { 0, 1 spotlight radius 10 falloff 20 tightness 5 cylinder }";
  is "spotlight shadowless: a point light" ("point", true) "light_source { 0, 1 spotlight shadowless }";
  is "shadowless spotlight: shadows" ("spot", false) "light_source { 0, 1 shadowless spotlight }";
  is "parallel spotlight" ("parallel", false) "light_source { 0, 1 parallel spotlight point_at -y }";
  is "spotlight parallel" ("parallel", false) "light_source { 0, 1 spotlight parallel point_at -y }";
  is "cylinder parallel" ("cylinder 0.75 1 0", false) "light_source { 0, 1 cylinder parallel }";
  (* point_at transformed with the light *)
  let s = Scn.compile "light_source { 0, 1 cylinder point_at y rotate 90*z translate x }" in
  match s.lights.(0).kind with
  | Light.Cylinder { point_at; _ } ->
      check "point_at turned x" 0. point_at.x;
      check "point_at turned y" 0. point_at.y
  | _ -> Alcotest.fail "not a cylinder"

(* projected_through: pixels of a plane lit from <0,0,-5> through a ball
   of radius 0.5 at z = -2 (diffuse 1, head on: 1 where lit) *)
let projected () =
  let scene ?(light = "") ?(extra = "") ?(ball = "sphere { <0, 0, -2>, 0.5 }") x =
    Scn.pixel
      (Printf.sprintf
         "camera { orthographic location <%g, 0, -10> look_at <%g, 0, 0> right 0.01*x up 0.01*y }
          light_source { <0, 0, -5>, rgb 1 %s projected_through { %s } }
          plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
%s" x x light ball extra)
  in
  Scn.gray "through the ball" 1. (scene 0.);
  Scn.gray "beside it" 0. (scene 1.);
  (* the ball's shadow of a point light: |x| < 0.5 * 5/3 (about 0.83) *)
  Scn.gray "its rim" (5. /. Float.sqrt 25.64) (scene 0.8);
  Scn.gray "just outside its rim" 0. (scene 0.85);
  let block z = Printf.sprintf "box { <-0.2, -0.2, %g>, <0.2, 0.2, %g> pigment { rgb 1 } no_image }" (z -. 0.1) (z +. 0.1) in
  Scn.gray "a block between the ball and the light casts no shadow" 1. (scene ~extra:(block (-3.5)) 0.);
  Scn.gray "a block between the plane and the ball does" 0. (scene ~extra:(block (-1.)) 0.);
  Scn.gray "shadowless: no shadow" 1. (scene ~light:"shadowless" ~extra:(block (-1.)) 0.);
  Scn.gray "shadowless: still through the ball only" 0. (scene ~light:"shadowless" 1.);
  (* the plane through the ball: inside it lit (its way out is the crossing) *)
  Scn.gray "inside the object" 1. (scene ~ball:"sphere { 0, 0.5 }" 0.);
  let c = 5. /. Float.sqrt 25.16 in
  Scn.gray "inside, off the axis" c (scene ~ball:"sphere { 0, 0.5 }" 0.4);
  (* the object's own surface facing the light: no crossing ahead *)
  let lit_face =
    Scn.pixel
      "camera { orthographic location <0, 0, -10> look_at 0 right 0.01*x up 0.01*y }
       light_source { <0, 0, -5>, rgb 1 projected_through { sphere { <0, 0, -2>, 0.5 } } }
       sphere { <0, 0, -2>, 0.5 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }"
  in
  Scn.gray "its own face toward the light" 0. lit_face;
  (* transformations written after projected_through move the object,
     those before do not *)
  let bounds text =
    match (Scn.compile text).lights.(0).projected_through with
    | Some o -> (match Object.bounds o with Some (lo, hi) -> Vec3.scale 0.5 (Vec3.add lo hi) | None -> Vec3.zero)
    | None -> Alcotest.fail "no projected_through"
  in
  let c = bounds "light_source { 0, 1 translate 5*x projected_through { sphere { 0, 1 } } translate y }" in
  check "not moved by the translate before" 0. c.x;
  check "moved by the translate after" 1. c.y

(* POV-Ray's shadow tolerance: what a shadow ray meets within 1e-3 of
   the light casts no shadow (trace.cpp, SHADOW_TOLERANCE). The light 5
   above and 5 before a lit wall point, head-on cosine 1/sqrt 2; a ceiling
   plane crossed 0.0004 sqrt 2 (inside the tolerance) or 0.002 sqrt 2
   (outside) short of the light. A light in a ceiling's own plane (the
   Cornell box's) was hidden by rounding, at random. *)
let shadow_tolerance () =
  let at ceiling =
    Scn.pixel
      (Printf.sprintf
         "light_source { <0,5,-4>, rgb 1 }\n\
          plane { y, %s pigment { rgb 1 } }\n\
          plane { z, 1 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }"
         ceiling)
  in
  Scn.gray "no ceiling" (1. /. Float.sqrt 2.) (at "100");
  Scn.gray "a ceiling 0.0004 under the light" (1. /. Float.sqrt 2.) (at "4.9996");
  Scn.gray "a ceiling 0.002 under the light" 0. (at "4.998")

let tests =
  ( "light",
    [
      Alcotest.test_case "recursive averaging" `Quick averaging;
      Alcotest.test_case "shadow tolerance: nothing within 1e-3 of the light hides it" `Quick shadow_tolerance;
      Alcotest.test_case "adaptive" `Quick adaptive;
      Alcotest.test_case "sample positions" `Quick positions;
      Alcotest.test_case "orient and circular: POV-Ray's axes and disc" `Quick orient_rules;
      Alcotest.test_case "orient makes a light circular; circular needs 2 samples an axis" `Quick orient_circular;
      Alcotest.test_case "area light in a scene" `Quick scene;
      Alcotest.test_case "shadows kept per point" `Quick kept_shadows;
      Alcotest.test_case "light_group sets" `Quick groups;
      Alcotest.test_case "area_illumination: shadow times the samples' mean" `Quick area_illumination;
      Alcotest.test_case "cylinder light: POV-Ray's formula by hand" `Quick cylinder_formula;
      Alcotest.test_case "cylinder light: axis, plane, direction, fade" `Quick cylinder_light_at;
      QCheck_alcotest.to_alcotest cylinder_parallel;
      Alcotest.test_case "cylinder light in a scene: pool and parallel shadow" `Quick cylinder_scene;
      Alcotest.test_case "light types switched as POV-Ray's parser does" `Quick light_types;
      Alcotest.test_case "projected_through: through, beside, shadows, inside, own face, transforms" `Quick projected;
    ] )
