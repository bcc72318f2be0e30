(* uv_mapping: POV-Ray 3.7's uv coordinates per shape (known answers
   measured by rendering uv as colour in POV-Ray), their range, and
   uv-mapped textures through the scene language. *)
open Camlray
open Helpers

let uv shape ?(id = 0.) x y z =
  let p = Vec3.m () and out = Vec3.m () and h = Hit.create infinity in
  h.id <- id;
  Vec3.set p x y z;
  Shape.uv_into shape p h out;
  (out.mx, out.my)

let check_uv msg (eu, ev) (u, v) =
  if not (close ~eps:1e-3 eu u && close ~eps:1e-3 ev v) then
    Alcotest.failf "%s: expected <%g, %g>, got <%g, %g>" msg eu ev u v

let sphere () =
  let s = Shape.sphere (Vec3.make 1. 2. 3.) 2. in
  check_uv "+x" (0., 0.5) (uv s 3. 2. 3.);
  check_uv "+z" (0.25, 0.5) (uv s 1. 2. 5.);
  check_uv "-x" (0.5, 0.5) (uv s (-1.) 2. 3.);
  check_uv "-z" (0.75, 0.5) (uv s 1. 2. 1.);
  check_uv "north pole" (0., 1.) (uv s 1. 4. 3.);
  check_uv "south pole" (0., 0.) (uv s 1. 0. 3.);
  (* POV-Ray's value at a pixel of a unit sphere: 0.5 + asin(0.75) / pi *)
  check_uv "latitude" (0.75, 0.5 +. (Float.asin 0.75 /. Float.pi)) (uv s 1. 3.5 (3. -. Float.sqrt (4. -. 2.25)))

let box () =
  let b = Shape.box (Vec3.make (-0.8) (-0.8) (-0.8)) (Vec3.make 0.8 0.8 0.8) in
  (* read from POV-Ray's picture of the -z face: x = -0.625, y = 0.625 *)
  check_uv "-z face" (0.9727, 0.6302) (uv b ~id:4. (-0.625) 0.625 (-0.8));
  check_uv "+z face" (0.4727, 0.6302) (uv b ~id:5. 0.625 0.625 0.8);
  check_uv "-x face" (0.2227, 0.6302) (uv b ~id:0. (-0.8) 0.625 0.625);
  check_uv "+x face" (0.7227, 0.6302) (uv b ~id:1. 0.8 0.625 (-0.625));
  check_uv "+y face" (0.2773, 0.7031) (uv b ~id:3. (-0.625) 0.8 0.625);
  check_uv "-y face" (0.2773, 0.0365) (uv b ~id:2. (-0.625) (-0.8) (-0.625))

let torus () =
  let t = Shape.Torus { major = 0.7; minor = 0.28 } in
  check_uv "outer -x" (0., 0.5) (uv t (-0.98) 0. 0.);
  check_uv "top +z" (0.25, 0.75) (uv t 0. 0.28 0.7);
  check_uv "outer +x" (0.5, 0.5) (uv t 0.98 0. 0.);
  check_uv "bottom -z" (0.75, 0.25) (uv t 0. (-0.28) (-0.7))

let mesh () =
  let verts = Float.Array.of_list [ 0.; 0.; 0.; 1.; 0.; 0.; 0.; 1.; 0. ] in
  let uvs = Float.Array.of_list [ 0.1; 0.2; 0.9; 0.3; 0.5; 0.8 ] in
  let mk uv =
    Mesh.make ?uv ~par:None ~verts ~normals:(Float.Array.create 0) ~faces:[| 0; 1; 2 |] ~normal_faces:[||]
      ~inside_vector:None ()
  in
  let h = Hit.create infinity and out = Vec3.m () in
  h.id <- 0.;
  h.u <- 0.5;
  h.v <- 0.25;
  Mesh.uv_into (mk (Some (uvs, [| 0; 1; 2 |]))) h out;
  check_uv "barycentric" ((0.25 *. 0.1) +. (0.5 *. 0.9) +. (0.25 *. 0.5), (0.25 *. 0.2) +. (0.5 *. 0.3) +. (0.25 *. 0.8))
    (out.mx, out.my);
  Mesh.uv_into (mk None) h out;
  check_uv "no uv_vectors" (0., 0.) (out.mx, out.my)

let in_unit (u, v) = u >= 0. && u <= 1. && v >= 0. && v <= 1.

let range =
  QCheck.Test.make ~name:"sphere and torus uv lie in [0, 1]" ~count:2000
    QCheck.(triple (float_range (-1.) 1.) (float_range (-1.) 1.) (float_range (-1.) 1.))
    (fun (x, y, z) ->
      let l = Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) in
      QCheck.assume (l > 1e-6);
      let s = Shape.sphere Vec3.zero 1. in
      let t = Shape.Torus { major = 1.; minor = 0.3 } in
      in_unit (uv s (x /. l) (y /. l) (z /. l)) && in_unit (uv t x y z))

let scene body =
  Printf.sprintf
    "camera { orthographic location <0, 0, -5> look_at 0 right x*2.6667 up y*2 }\n\
     #declare UV = pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } }\n%s" body

let img body = render_whitted ~width:16 ~height:12 (scene body)

let same msg a b =
  for y = 0 to 11 do
    for x = 0 to 15 do
      if pixel a x y <> pixel b x y then Alcotest.failf "%s: pixel %d,%d differs" msg x y
    done
  done

(* as POV-Ray: the object's scale leaves uv alone, a pigment's own scale
   scales it, a scale after a uv-mapped pigment (in the texture) leaves it *)
let transforms () =
  let f = "finish { ambient 1 diffuse 0 }" in
  let base = img (Printf.sprintf "sphere { 0, 1 pigment { uv_mapping UV } %s }" f) in
  same "object scale" base (img (Printf.sprintf "sphere { 0, 0.5 pigment { uv_mapping UV } %s scale 2 }" f));
  same "texture scale after the pigment" base
    (img (Printf.sprintf "sphere { 0, 1 texture { pigment { uv_mapping UV } %s scale 0.5 } }" f));
  same "object-level uv_mapping" base (img (Printf.sprintf "sphere { 0, 1 uv_mapping pigment { UV } %s }" f));
  same "texture-level uv_mapping" base
    (img (Printf.sprintf "sphere { 0, 1 texture { uv_mapping pigment { UV } %s } }" f));
  let r, _, _ = pixel base 8 6 in
  (* the front of the sphere, just right of the centre: u a little past 0.75 *)
  if not (r > 0.75 && r < 0.85) then Alcotest.failf "front u: %g" r;
  let r2, _, _ = pixel (img (Printf.sprintf "sphere { 0, 1 pigment { uv_mapping UV scale 0.5 } %s }" f)) 8 6 in
  if not (close ~eps:1e-6 r2 (Float.rem (2. *. r) 1.)) then Alcotest.failf "pigment scale: %g for %g" r2 r

let tests =
  ( "uv",
    [
      Alcotest.test_case "sphere" `Quick sphere;
      Alcotest.test_case "box" `Quick box;
      Alcotest.test_case "torus" `Quick torus;
      Alcotest.test_case "mesh" `Quick mesh;
      QCheck_alcotest.to_alcotest range;
      Alcotest.test_case "transforms and forms" `Quick transforms;
    ] )
