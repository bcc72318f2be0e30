(* POV-Ray 3.7.0's mesh_camera, built through the scene language: its rays
   against hand-computed answers (centroid, normal sign, location's push,
   direction's flip, a transform applied to the normal as a normal, the
   four distributions, the uv lookup's barycentric point and the smooth
   normal), the pixel rule POV-Ray 3.7.0 follows, what whitted makes of
   the rays, and the refusal in mc mode. *)
open Camlray

let mesh_camera text =
  match (Helpers.compile_string ("#version 3.7;\n" ^ text)).camera.projection with
  | Camera.Mesh m -> m
  | _ -> Alcotest.fail "not a mesh camera"

(* ray [k] of the image point (px, py): [Some (origin, direction)] *)
let ray ?(k = 0) m ~w ~h px py =
  let o = Vec3.m () and d = Vec3.m () in
  Vec3.set o px py 0.;
  if Mesh_camera.ray_into m ~width:w ~height:h k o d then Some (Vec3.of_m o, Vec3.of_m d) else None

(* the ray of pixel (i, j)'s centre *)
let pixel ?k m ~w ~h i j = ray ?k m ~w ~h (float_of_int i +. 0.5) (float_of_int j +. 0.5)

let vec = Alcotest.testable (fun f (v : Vec3.t) -> Format.fprintf f "<%g, %g, %g>" v.x v.y v.z) (fun a b -> Vec3.dist a b < 1e-6)

let check_ray what ~origin ~dir r =
  match r with
  | None -> Alcotest.failf "%s: no ray" what
  | Some (o, d) ->
      Alcotest.check vec (what ^ ": origin") origin o;
      Alcotest.check vec (what ^ ": direction") (Vec3.normalize dir) d

let no_ray what r = Alcotest.(check bool) (what ^ ": no ray") true (r = None)
let third = 1. /. 3.

(* two faces: face 0 (normal +z, centroid <1/3, 1/3, 0>), face 1 (normal
   -z, centroid <2/3, 2/3, 0>): the normal is (P3 - P1) x (P2 - P1) *)
let two = "mesh { triangle { <0,0,0>, <0,1,0>, <1,0,0> } triangle { <1,1,0>, <0,1,0>, <1,0,0> } }"

let centroid_and_normal () =
  let m = mesh_camera (Printf.sprintf "camera { mesh_camera { 1 0 %s } location 0 }" two) in
  check_ray "face 0" ~origin:(Vec3.make third third 0.) ~dir:Vec3.unit_z (pixel m ~w:2 ~h:1 0 0);
  check_ray "face 1" ~origin:(Vec3.make (2. *. third) (2. *. third) 0.) ~dir:(Vec3.neg Vec3.unit_z)
    (pixel m ~w:2 ~h:1 1 0);
  (* a 3 x 1 image: pixel 2 has no face *)
  no_ray "pixel 2" (pixel m ~w:3 ~h:1 2 0)

let push_and_flip () =
  (* location's z moves the start along the normal; a direction with z <
     0 turns the ray round after the move *)
  let m = mesh_camera (Printf.sprintf "camera { mesh_camera { 1 0 %s } location <7, 8, 0.5> }" two) in
  check_ray "pushed" ~origin:(Vec3.make third third 0.5) ~dir:Vec3.unit_z (pixel m ~w:2 ~h:1 0 0);
  check_ray "pushed down" ~origin:(Vec3.make (2. *. third) (2. *. third) (-0.5)) ~dir:(Vec3.neg Vec3.unit_z)
    (pixel m ~w:2 ~h:1 1 0);
  let m = mesh_camera (Printf.sprintf "camera { mesh_camera { 1 0 %s } location <0, 0, 0.5> direction -z }" two) in
  check_ray "flipped" ~origin:(Vec3.make third third 0.5) ~dir:(Vec3.neg Vec3.unit_z) (pixel m ~w:2 ~h:1 0 0);
  let m = mesh_camera (Printf.sprintf "camera { mesh_camera { 1 0 %s } direction <0, 0, -1e-11> }" two) in
  check_ray "-1e-11 is not below -1e-10" ~origin:(Vec3.make third third 0.) ~dir:Vec3.unit_z (pixel m ~w:2 ~h:1 0 0)

let transform () =
  (* the face x + z = 0 through <0,0,0>, <0,1,0>, <1,0,-1>: normal
     <1, 0, 1>; scaled by <2, 1, 1> it turns as a normal, to <1/2, 0, 1>,
     not as a direction (<2, 0, 1>) *)
  let m =
    mesh_camera
      "camera { mesh_camera { 1 0 mesh { triangle { <0,0,0>, <0,1,0>, <1,0,-1> } scale <2, 1, 1> translate <0, 0, 5> } } }"
  in
  check_ray "scaled" ~origin:(Vec3.make (2. *. third) third (5. -. third)) ~dir:(Vec3.make 0.5 0. 1.)
    (pixel m ~w:1 ~h:1 0 0);
  let m =
    mesh_camera
      "camera { mesh_camera { 1 0 mesh { triangle { <0,0,0>, <0,1,0>, <1,0,0> } rotate 90*y translate x } } location <0, 0, 1> }"
  in
  (* pushed in mesh space to <1/3, 1/3, 1>, then turned: +z goes to +x *)
  check_ray "turned" ~origin:(Vec3.make 2. third (-.third)) ~dir:Vec3.unit_x (pixel m ~w:1 ~h:1 0 0)

(* a mesh of [n] faces along x, face f with centroid x = f + 0.5 *)
let row n z =
  let b = Buffer.create 256 in
  Buffer.add_string b "mesh { ";
  for f = 0 to n - 1 do
    Printf.bprintf b "triangle { <%d, 0, %g>, <%d, 1, %g>, <%d.5, 0, %g> } " f z f z f z
  done;
  Buffer.add_string b "}";
  Buffer.contents b

(* the face a ray of [row] starts from (its centroid is at x = f + 1/6) *)
let face_x r = match r with Some ((o : Vec3.t), _) -> Float.round o.x | None -> -1.

(* a mesh's text with modifiers added *)
let placed mesh mods = String.sub mesh 0 (String.length mesh - 1) ^ mods ^ " }"

let pixel_rule () =
  (* POV-Ray 3.7.0: row j reads the faces of row j - 1, row 0 its own *)
  let m = mesh_camera (Printf.sprintf "camera { mesh_camera { 1 0 %s } }" (row 20 0.)) in
  let face i j = int_of_float (Float.round (face_x (pixel m ~w:3 ~h:5 i j) *. 1.)) in
  let got = List.init 5 (fun j -> List.init 3 (fun i -> face i j)) in
  Alcotest.(check (list (list int))) "faces" [ [ 0; 1; 2 ]; [ 0; 1; 2 ]; [ 3; 4; 5 ]; [ 6; 7; 8 ]; [ 9; 10; 11 ] ] got;
  (* points outside the image are clamped to it *)
  Alcotest.(check int) "left of the image" 0 (int_of_float (face_x (ray m ~w:3 ~h:5 (-3.) (-3.))));
  Alcotest.(check int) "right of the image" 14 (int_of_float (face_x (ray m ~w:3 ~h:5 9. 9.)))

let per_mesh () =
  (* distribution 0: ray k from mesh k; a mesh too short shoots no ray *)
  let m = mesh_camera (Printf.sprintf "camera { mesh_camera { 2 0 %s %s } }" (row 2 0.) (row 1 1.)) in
  let z r = match r with Some ((o : Vec3.t), _) -> o.z | None -> -1. in
  Alcotest.(check (float 0.)) "ray 0 from mesh 0" 0. (z (pixel ~k:0 m ~w:2 ~h:1 1 0));
  Alcotest.(check (float 0.)) "ray 1 from mesh 1" 1. (z (pixel ~k:1 m ~w:2 ~h:1 0 0));
  no_ray "mesh 1 has no face 1" (pixel ~k:1 m ~w:2 ~h:1 1 0)

let summed () =
  (* distribution 1: mesh 0's faces, then mesh 1's; ray k from face
     pixel + k * total, so ray 1 is never shot *)
  let m = mesh_camera (Printf.sprintf "camera { mesh_camera { 2 1 %s %s } }" (row 2 0.) (row 3 1.)) in
  let at r = match r with Some ((o : Vec3.t), _) -> (o.z, face_x r) | None -> (-1., -1.) in
  Alcotest.(check (pair (float 0.) (float 1e-6))) "pixel 1" (0., 1.) (at (pixel m ~w:5 ~h:1 1 0));
  Alcotest.(check (pair (float 0.) (float 1e-6))) "pixel 2: mesh 1's face 0" (1., 0.) (at (pixel m ~w:5 ~h:1 2 0));
  Alcotest.(check (pair (float 0.) (float 1e-6))) "pixel 4: mesh 1's face 2" (1., 2.) (at (pixel m ~w:5 ~h:1 4 0));
  no_ray "ray 1" (pixel ~k:1 m ~w:5 ~h:1 0 0);
  no_ray "pixel 5" (pixel m ~w:6 ~h:1 5 0)

let side_by_side () =
  (* distribution 2: mesh floor(x / (width / meshes)), face row * (width
     / meshes) + column, the column from the image's left edge (POV-Ray's
     rule) *)
  let m = mesh_camera (Printf.sprintf "camera { mesh_camera { 1 2 %s %s } }" (row 8 0.) (row 8 1.)) in
  let at r = match r with Some ((o : Vec3.t), _) -> (o.z, face_x r) | None -> (-1., -1.) in
  let p = Alcotest.(pair (float 0.) (float 1e-6)) in
  Alcotest.check p "x 1" (0., 1.) (at (pixel m ~w:4 ~h:3 1 0));
  Alcotest.check p "x 2: mesh 1, face 2" (1., 2.) (at (pixel m ~w:4 ~h:3 2 0));
  Alcotest.check p "x 3, row 2 (reads row 1): face 1 * 2 + 3" (1., 5.) (at (pixel m ~w:4 ~h:3 3 2));
  (* width 5, 2 meshes: strips of 2.5 pixels, faces 2 a row; the point
     divided is the pixel's centre, 2.5 for x 2 (checked with POV-Ray
     3.7.0: of 5 pixels, 2 from mesh 0, 3 from mesh 1) *)
  Alcotest.check p "width 5, x 1" (0., 1.) (at (pixel m ~w:5 ~h:1 1 0));
  Alcotest.check p "width 5, x 2" (1., 2.) (at (pixel m ~w:5 ~h:1 2 0))

(* two faces covering [0,2]^2, uv the corners' xy halved *)
let square =
  "mesh { triangle { <0,0,0>, <0,2,0>, <2,0,0> uv_vectors <0,0>, <0,1>, <1,0> } \
   triangle { <2,2,0>, <2,0,0>, <0,2,0> uv_vectors <1,1>, <1,0>, <0,1> } }"

let uv_map () =
  (* the point (x, y) = (px, py - 1) clamped; u = (x - 0.5) / w, v = 1 -
     (y + 0.5) / h; the origin the barycentric point, here 2 (u, v) *)
  let m = mesh_camera (Printf.sprintf "camera { mesh_camera { 1 3 %s } }" square) in
  let at u v = Vec3.make (2. *. u) (2. *. v) 0. in
  check_ray "pixel (1, 2)" ~origin:(at 0.25 0.5) ~dir:Vec3.unit_z (pixel m ~w:4 ~h:4 1 2);
  check_ray "a point inside pixel (1, 2)" ~origin:(at (1.2 /. 4.) (1. -. (2.4 /. 4.))) ~dir:Vec3.unit_z
    (ray m ~w:4 ~h:4 1.7 2.9);
  check_ray "last column, first row" ~origin:(at (2.5 /. 4.) (1. -. (0.5 /. 4.))) ~dir:Vec3.unit_z
    (pixel m ~w:4 ~h:4 3 0);
  (* the first face in index order holding the point: a third face over
     the first two, listed last, is never used; listed first, always *)
  let cover = "triangle { <0,0,1>, <0,4,1>, <4,0,1> uv_vectors <0,0>, <0,2>, <2,0> }" in
  let last = String.sub square 0 (String.length square - 1) ^ cover ^ " }" in
  let m = mesh_camera (Printf.sprintf "camera { mesh_camera { 1 3 %s } }" last) in
  check_ray "covered last" ~origin:(at 0.25 0.5) ~dir:Vec3.unit_z (pixel m ~w:4 ~h:4 1 2);
  let first = "mesh { " ^ cover ^ String.sub square 6 (String.length square - 6) in
  let m = mesh_camera (Printf.sprintf "camera { mesh_camera { 1 3 %s } }" first) in
  check_ray "covered first" ~origin:(Vec3.make 0.5 1. 1.) ~dir:Vec3.unit_z (pixel m ~w:4 ~h:4 1 2);
  (* no face there: no ray *)
  let m =
    mesh_camera
      "camera { mesh_camera { 1 3 mesh { triangle { <0,0,0>, <0,1,0>, <1,0,0> uv_vectors <0,0>, <0,0.5>, <0.5,0> } } } }"
  in
  no_ray "outside the uv triangle" (pixel m ~w:4 ~h:4 3 3)

let smooth () =
  (* at barycentric weights (B1, B2, B3) the direction is B1 N1 + B2 N2 +
     B3 N3 (unit normals), normalised; the push goes along that blend
     before it is normalised, as POV-Ray's Smooth_Mesh_Normal gives it *)
  let n1 = Vec3.normalize (Vec3.make (-1.) 0. 1.) and n2 = Vec3.unit_z and n3 = Vec3.normalize (Vec3.make 0. 1. 1.) in
  let tri =
    "mesh { smooth_triangle { <0,0,0>, <-1,0,1>, <0,4,0>, <0,0,1>, <4,0,0>, <0,1,1> \
     uv_vectors <0,0>, <0,1>, <1,0> } }"
  in
  (* pixel (1, 3) of 8 x 8: u = 1/8, v = 1 - 3/8 *)
  let u = 1. /. 8. and v = 1. -. (3. /. 8.) in
  let b1 = 1. -. u -. v and b2 = v and b3 = u in
  let blend = Vec3.add (Vec3.scale b1 n1) (Vec3.add (Vec3.scale b2 n2) (Vec3.scale b3 n3)) in
  let p = Vec3.make (4. *. u) (4. *. v) 0. in
  let m = mesh_camera (Printf.sprintf "camera { mesh_camera { 1 3 %s smooth } location <0, 0, 0.5> }" tri) in
  check_ray "smooth" ~origin:(Vec3.madd p 0.5 blend) ~dir:blend (pixel m ~w:8 ~h:8 1 3);
  let m = mesh_camera (Printf.sprintf "camera { mesh_camera { 1 3 %s } location <0, 0, 0.5> }" tri) in
  check_ray "not smooth: the face normal" ~origin:(Vec3.madd p 0.5 Vec3.unit_z) ~dir:Vec3.unit_z
    (pixel m ~w:8 ~h:8 1 3)

let degenerate () =
  (* a face with no area is dropped: the faces after it move up *)
  let m =
    mesh_camera
      "camera { mesh_camera { 1 0 mesh { triangle { <0,0,0>, <1,0,0>, <2,0,0> } triangle { <5,0,0>, <5,1,0>, <6,0,0> } } } }"
  in
  check_ray "face 0 is the second" ~origin:(Vec3.make (16. /. 3.) third 0.) ~dir:Vec3.unit_z (pixel m ~w:2 ~h:1 0 0);
  no_ray "one face" (pixel m ~w:2 ~h:1 1 0)

let no_allocation () =
  let m = mesh_camera (Printf.sprintf "camera { mesh_camera { 1 0 %s } }" (placed (row 16 0.) " rotate 30*y")) in
  let u = mesh_camera (Printf.sprintf "camera { mesh_camera { 1 3 %s smooth } location 0.1*z }"
                         "mesh { smooth_triangle { <0,0,0>, <-1,0,1>, <0,4,0>, <0,0,1>, <4,0,0>, <0,1,1> uv_vectors <0,0>, <0,1>, <1,0> } }") in
  let o = Vec3.m () and d = Vec3.m () in
  let run c =
    for i = 0 to 999 do
      Vec3.set o (float_of_int (i land 15) +. 0.5) 0.5 0.;
      ignore (Mesh_camera.ray_into c ~width:16 ~height:1 0 o d)
    done
  in
  run m;
  run u;
  let before = Gc.minor_words () in
  run m;
  run u;
  let words = Gc.minor_words () -. before in
  if words > 8. then Alcotest.failf "2000 mesh camera rays allocated %.0f words" words

(* whitted's path for a mesh camera allocates nothing either: minor
   words per pixel of a one-domain 64x48 render (2 rays a pixel), the
   second of two (the first makes the domain's scratch) *)
let whitted_allocation () =
  let width = 64 and height = 48 in
  let b = Buffer.create 65536 in
  Buffer.add_string b "mesh { ";
  for j = 0 to height - 1 do
    for i = 0 to width - 1 do
      let x = (float_of_int i /. 16.) -. 2. and y = 1.5 -. (float_of_int j /. 16.) in
      Printf.bprintf b "triangle { <%g, %g, 0>, <%g, %g, 0>, <%g, %g, 0> } " x y x (y +. 0.05) (x +. 0.05) y
    done
  done;
  Buffer.add_string b "}";
  let mesh = Buffer.contents b in
  let s =
    Helpers.compile_string
      (Printf.sprintf
         "#version 3.7;
camera { mesh_camera { 2 0 %s %s } location <0, 0, -4> }
          light_source { <-4, 6, -5>, rgb 1 }
          plane { z, 3 pigment { checker rgb 1, rgb <0.1, 0.2, 0.5> } }
          sphere { <0, 0, 1>, 1 pigment { rgb <0.8, 0.3, 0.2> } finish { reflection 0.3 } }"
         mesh (placed mesh " rotate 2*y"))
  in
  let pixel = Whitted.pixel_into s ~width ~height in
  ignore (Render.image_into ~domains:1 ~width ~height pixel);
  let before = Gc.minor_words () in
  ignore (Render.image_into ~domains:1 ~width ~height pixel);
  let words = (Gc.minor_words () -. before) /. float_of_int (width * height) in
  if words > 0.1 then Alcotest.failf "%.2f words per pixel of a mesh camera (at most 0.1)" words

(* whitted: the mean of the rays shot, black where none is *)
let whitted_mean () =
  let img =
    Helpers.render_whitted ~width:2 ~height:1
      (Printf.sprintf
         "#version 3.7;\nglobal_settings { assumed_gamma 1 }\nbackground { rgb <0, 0, 1> }\n\
          camera { mesh_camera { 2 0 %s mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } } } location 0 }\n\
          plane { z, 5 pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 } }"
         (row 2 0.))
  in
  (* pixel 0: mesh 0 looks at the plane, mesh 1 (normal -z) at the
     background; pixel 1: mesh 1 has no face 1, only mesh 0's ray *)
  let r, g, b = Helpers.pixel img 0 0 in
  Alcotest.(check (list (float 1e-9))) "pixel 0: the mean" [ 0.5; 0.; 0.5 ] [ r; g; b ];
  let r, g, b = Helpers.pixel img 1 0 in
  Alcotest.(check (list (float 1e-9))) "pixel 1: one ray" [ 1.; 0.; 0. ] [ r; g; b ];
  let img =
    Helpers.render_whitted ~width:2 ~height:1
      "#version 3.7;\nbackground { rgb 1 }\ncamera { mesh_camera { 1 0 mesh { triangle { 0, x, y } } } }"
  in
  let r, g, b = Helpers.pixel img 1 0 in
  Alcotest.(check (list (float 0.))) "no face: black" [ 0.; 0.; 0. ] [ r; g; b ]

let max_distance () =
  let scene far =
    Printf.sprintf
      "#version 3.7;\nbackground { rgb <0, 0, 1> }\ncamera { mesh_camera { 1 0 %s %s } }\n\
       plane { z, 5 pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 } }"
      far (row 1 0.)
  in
  let seen far = let r, _, _ = Helpers.pixel (Helpers.render_whitted ~width:1 ~height:1 (scene far)) 0 0 in r in
  Alcotest.(check (float 0.)) "no limit" 1. (seen "");
  Alcotest.(check (float 0.)) "6" 1. (seen "6");
  Alcotest.(check (float 0.)) "2: nothing that far" 0. (seen "2")

let mc_refused () =
  let d = Helpers.temp_dir () in
  let scene = Filename.concat d "m.pov" in
  Helpers.write_file scene "#version 3.7;\ncamera {\n  mesh_camera { 1 0 mesh { triangle { 0, x, y } } }\n}\n";
  let code, _, err = Helpers.run [ "render"; scene; "--mode"; "mc"; "-W"; "4"; "-H"; "4"; "-o"; Filename.concat d "m.png" ] in
  Alcotest.(check int) "exit 1" 1 code;
  Alcotest.(check bool) ("located: " ^ err) true (Helpers.contains err "m.pov:3:3: error: mesh_camera is rendered in whitted mode only");
  let code, _, err = Helpers.run [ "render"; scene; "-W"; "4"; "-H"; "4"; "-q"; "-o"; Filename.concat d "w.png" ] in
  Alcotest.(check int) ("whitted renders it: " ^ err) 0 code

let tests =
  ( "mesh_camera",
    [
      Alcotest.test_case "centroid, normal (P3 - P1) x (P2 - P1), no face: no ray" `Quick centroid_and_normal;
      Alcotest.test_case "location's z pushes along the normal; direction's z < -1e-10 flips" `Quick push_and_flip;
      Alcotest.test_case "the transform: origin as a point, direction as a normal" `Quick transform;
      Alcotest.test_case "POV-Ray 3.7.0's pixel rule: row j reads row j - 1, clamped" `Quick pixel_rule;
      Alcotest.test_case "distribution 0: ray k from mesh k" `Quick per_mesh;
      Alcotest.test_case "distribution 1: the meshes summed" `Quick summed;
      Alcotest.test_case "distribution 2: side by side" `Quick side_by_side;
      Alcotest.test_case "distribution 3: the first face holding (u, v), barycentric" `Quick uv_map;
      Alcotest.test_case "distribution 3 with smooth: the blended normal" `Quick smooth;
      Alcotest.test_case "degenerate faces dropped from the indices" `Quick degenerate;
      Alcotest.test_case "rays allocate nothing" `Quick no_allocation;
      Alcotest.test_case "whitted's mesh camera path allocates nothing" `Quick whitted_allocation;
      Alcotest.test_case "whitted: the mean of the rays shot, black for none" `Quick whitted_mean;
      Alcotest.test_case "the third number limits how far rays see" `Quick max_distance;
      Alcotest.test_case "mc mode refuses it with a located error" `Quick mc_refused;
    ] )
