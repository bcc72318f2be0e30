(* uv_mapping: POV-Ray 3.7's uv coordinates per shape (known answers
   measured by rendering uv as colour in POV-Ray), their range,
   uv-mapped textures through the scene language, and uv-mapped normals
   against POV-Ray's shading. *)
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

(* uv-mapped normals against POV-Ray 3.7: 1x1 probes of a lit surface
   hit at the origin (camera at -5z), diffuse 1, no ambient, under three
   lights: red from -z, green from <1,0,-1>, blue from <0,1,-1> (so the
   three channels are the perturbed normal's three components). POV-Ray's
   values were read from +FN16 File_Gamma=1.0 renders; 16-bit, so good to
   about 2e-5. *)
let probe body =
  Scn.pixel
    ("camera { location <0,0,-5> look_at 0 }\n\
      light_source { <0,0,-1000>, rgb <1,0,0> }\n\
      light_source { <1000,0,-1000>, rgb <0,1,0> }\n\
      light_source { <0,1000,-1000>, rgb <0,0,1> }\n\
      #default { finish { ambient 0 diffuse 1 } }\n" ^ body)

(* a mesh2 triangle in z = 0 whose corners' uv are given (u, v at the
   origin: the corners' mean) *)
let tri ?(uv = "<0.5,0.5>, <6.5,0.5>, <0.5,6.5>") rest =
  Printf.sprintf
    "mesh2 { vertex_vectors { 3, <-2,-2,0>, <4,-2,0>, <-2,4,0> } uv_vectors { 3, %s } face_indices { 1, <0,1,2> } %s }"
    uv rest

(* every corner at <2.5, 2.5>: the same uv wherever the ray meets it, so
   transformations of the object cannot move it *)
let still = "<2.5,2.5>, <2.5,2.5>, <2.5,2.5>"
let swapped = "<0.5,0.5>, <0.5,6.5>, <6.5,0.5>"
let uvtex n = Printf.sprintf "texture { uv_mapping pigment { rgb 1 } normal { %s } }" n
let turned = "rotate y*30 rotate x*-20"

let normals () =
  let c = Scn.color in
  (* no tangent frame: the pattern's slope along u tilts along world x
     whichever way u runs on the surface; a plain gradient x 0.5 in world
     space gives the same 0.99779 0.65850 0.70555 *)
  let ramp = (0.99779, 0.65850, 0.70555) in
  c "u along x" ramp (probe (tri "pigment { rgb 1 } normal { uv_mapping gradient x 0.5 }"));
  c "u along y, slope along u" ramp (probe (tri ~uv:swapped (uvtex "gradient x 0.5")));
  c "u along y, slope along v" (0.99779, 0.70555, 0.65850) (probe (tri ~uv:swapped (uvtex "gradient y 0.5")));
  c "the triangle wound the other way" ramp
    (probe
       "mesh2 { vertex_vectors { 3, <-2,-2,0>, <-2,4,0>, <4,-2,0> } uv_vectors { 3, <0.5,0.5>, <0.5,6.5>, <6.5,0.5> } \
        face_indices { 1, <0,1,2> } texture { uv_mapping pigment { rgb 1 } normal { gradient x 0.5 } } }");
  c "uv stretched: the same slope" ramp (probe (tri ~uv:"<0.5,0.5>, <12.5,0.5>, <0.5,3.5>" (uvtex "gradient x 0.5")));
  c "the normal's own scale" (0.99449, 0.63691, 0.67005) (probe (tri (uvtex "gradient <1,1,0> 0.5 scale <0.5,1,1>")));
  (* a texture's uv_mapping: the object's transformations turn the normal
     (its flat normal turned is 0.81379 0.22188 0.36600) *)
  c "turned, slope along u" (0.78074, 0.15856, 0.35113) (probe (tri (uvtex "gradient x 0.5" ^ " " ^ turned)));
  c "turned, slope along v" (0.78924, 0.20531, 0.30491) (probe (tri (uvtex "gradient y 0.5" ^ " " ^ turned)));
  c "turned, slope along the normal: flat" (0.81379, 0.22188, 0.36600)
    (probe (tri (uvtex "gradient z 0.5 translate 0.5*z" ^ " " ^ turned)));
  c "turned, slope along <1,2,3>" (0.79371, 0.19759, 0.33153)
    (probe (tri (uvtex "gradient <1,2,3> 0.5 translate 0.3" ^ " " ^ turned)));
  (* ... but do not move the point the pattern is taken at *)
  let wave = "gradient x 0.5 sine_wave" in
  let base = (0.97884, 0.83685, 0.69220) and squeezed = (0.95818, 0.87990, 0.67759) in
  c "sine wave at <2.5, 2.5>" base (probe (tri ~uv:still (uvtex wave)));
  c "translated after the texture: unmoved" base (probe (tri ~uv:still (uvtex wave ^ " translate 0.2*x")));
  c "scaled after the texture: turned, unmoved" squeezed
    (probe (tri ~uv:still (uvtex wave ^ " scale <0.7,1,1>")));
  c "a scale before the texture: nothing" base (probe (tri ~uv:still ("scale <0.7,1,1> " ^ uvtex wave)));
  c "translated inside the texture: moved" (0.99751, 0.75508, 0.70243)
    (probe (tri ~uv:still ("texture { uv_mapping pigment { rgb 1 } normal { " ^ wave ^ " } translate 0.2*x }")));
  c "a uv texture_map's normals turn the same way" squeezed
    (probe
       (tri ~uv:still
          ("texture { uv_mapping gradient x texture_map { [0 pigment { rgb 1 } normal { " ^ wave
         ^ " }] [1 pigment { rgb 1 } normal { " ^ wave ^ " }] } } scale <0.7,1,1>")));
  (* a normal's uv_mapping, or the object's: later transformations and
     modifiers do nothing *)
  let uvn = "pigment { rgb 1 } normal { uv_mapping " ^ wave ^ " }" in
  c "normal { uv_mapping }, scaled after" base (probe (tri ~uv:still (uvn ^ " scale <0.7,1,1>")));
  c "normal { uv_mapping } inside its own texture, scaled after" squeezed
    (probe (tri ~uv:still ("texture { uv_mapping pigment { rgb 1 } normal { uv_mapping " ^ wave ^ " } } scale <0.7,1,1>")));
  c "a declared uv normal turned, bump_size changed" base
    (probe
       ("#declare N = normal { uv_mapping " ^ wave ^ " }\n"
       ^ tri ~uv:still "pigment { rgb 1 } normal { N rotate z*45 bump_size 3 }"));
  c "the object's uv_mapping maps its normal" base
    (probe (tri ~uv:still ("uv_mapping pigment { rgb 1 } normal { " ^ wave ^ " } scale <0.7,1,1>")));
  c "the object's uv_mapping, the normal translated" (0.99751, 0.75508, 0.70243)
    (probe (tri ~uv:still ("uv_mapping pigment { rgb 1 } normal { " ^ wave ^ " translate 0.2*x }")));
  c "uv-mapped normal_map entries in a turned object" (0.83867, 0.27187, 0.38047)
    (probe
       (tri
          ("pigment { rgb 1 } normal { gradient x phase 0.3 normal_map { \
            [0 uv_mapping gradient y 0.5 sine_wave scale 0.4] [1 uv_mapping gradient x 0.8 sine_wave scale 0.3] } } "
         ^ turned)));
  (* curved surfaces; quilted (the balcony scene's table cloth) *)
  c "sphere, uv <0.75, 0.5>" (0.99779, 0.65812, 0.70518) (probe ("sphere { 0, 1 " ^ uvtex "gradient x 0.5" ^ " }"));
  c "sphere, scaled after" (0.99995, 0.70047, 0.70982)
    (probe ("sphere { 0, 1 " ^ uvtex wave ^ " scale <0.7,1,1> }"));
  c "box" (0.91302, 0.35732, 0.62571) (probe ("box { -1, 1 " ^ uvtex "gradient x 0.7 sine_wave scale 0.3" ^ " rotate <10,20,30> }"));
  c "quilted on the triangle" (0.74417, 0.12625, 0.27492) (probe (tri (uvtex "quilted 0.6 scale 0.3" ^ " " ^ turned)));
  c "quilted on a sphere" (0.95093, 0.45783, 0.62722)
    (probe ("sphere { 0, 1 " ^ uvtex "quilted 0.6 scale 0.08" ^ " rotate <10,20,30> }"));
  c "torus" (0.96869, 0.52415, 0.75560)
    (probe ("torus { 1, 0.4 rotate x*-90 translate <1,0,0> " ^ uvtex "gradient x 0.5 sine_wave scale 0.1" ^ " rotate <10,20,30> }"))

let normal_errors () =
  Scn.check_message "camera { normal { uv_mapping bumps 0.5 } }" "a camera's normal cannot be uv-mapped";
  Scn.check_message "sphere { 0, 1 pigment { rgb 1 } uv_mapping }" "uv_mapping must come before the object's texture";
  Scn.check_message "#declare O = sphere { 0, 1 finish { ambient 1 } }\nobject { O uv_mapping }"
    "uv_mapping must come before the object's texture";
  (* a CSG without a texture of its own may still take it *)
  ignore (Scn.compile "union { sphere { 0, 1 pigment { rgb 1 } } uv_mapping }");
  (* the object's uv flag is set by a uv-mapped normal alone *)
  let s = Scn.compile (tri "pigment { rgb 1 } normal { uv_mapping gradient x 0.5 }") in
  match s.Scene.objects with
  | [| o |] -> Alcotest.(check bool) "object needs uv" true o.Object.uv
  | l -> Alcotest.failf "%d objects" (Array.length l)

(* shadow rays read the uv where they cross a uv-mapped surface: a plane
   at z = 0 seen at the origin, lit from <1,0,-1> through a filtering
   uv-mapped occluder (POV-Ray 3.7's values, measured as above) *)
let shadows () =
  let lit light body =
    Scn.pixel
      (Printf.sprintf
         "camera { location <0,0,-5> look_at 0 }\n\
          light_source { <1000,0,-1000>, rgb %g }\n\
          #default { finish { ambient 0 diffuse 1 } }\n\
          plane { z, 0 pigment { rgb 1 } }\n%s" light body)
  in
  let filt g = Printf.sprintf "pigment { uv_mapping gradient %s color_map { [0 rgbf <1,0,0,1>] [1 rgbf <0,0,1,1>] } }" g in
  Scn.color "through a sphere" (0.02210, 0., 0.09281) (lit 0.4 ("sphere { <2,0,-2>, 0.8 " ^ filt "x" ^ " }"));
  Scn.color "through a box" (0.05304, 0., 0.05304)
    (lit 0.4 ("box { <1.4,-0.6,-2.6>, <2.6,0.6,-1.4> " ^ filt "x" ^ " }"));
  Scn.color "through a mesh2" (0.03510, 0., 0.03561)
    (lit 0.1
       ("mesh2 { vertex_vectors { 3, <0.5,-2,-3>, <0.5,2,-3>, <3,0,-0.2> } uv_vectors { 3, <0.1,0.1>, <0.9,0.2>, <0.3,0.9> } \
         face_indices { 1, <0,1,2> } " ^ filt "y" ^ " }"));
  (* faked caustics: the crossings' normals perturbed at their uv *)
  Scn.gray "caustics of a uv-mapped normal" 0.28260
    (lit 0.1
       "sphere { <2,0,-2>, 0.8 texture { uv_mapping pigment { rgbt 1 } normal { gradient x 0.5 sine_wave scale 0.1 } } \
        interior { caustics 1 } }")

(* mc mode reads the uv too: an emitting uv-mapped sphere seen through a
   tiny orthographic window gives whitted's colour, and a filtering
   uv-mapped sphere tints a shadow ray as whitted's does *)
let mc () =
  let both src =
    let s = Scn.compile src in
    (* no uv left over from an earlier render on this domain *)
    Pattern.set_uv 0. 0.;
    let m = Path.pixel (Path.prepare s) ~width:1 ~height:1 ~seed:1 ~spp:4 ~max_depth:4 0 0 in
    let w = Whitted.pixel s ~width:1 ~height:1 0 0 in
    (w, m)
  in
  let w, m =
    both
      "camera { orthographic location <0.2,0.1,-5> look_at <0.2,0.1,0> right 0.001*x up 0.001*y }\n\
       sphere { 0, 1 pigment { uv_mapping gradient x color_map { [0 rgb <0,0,1>] [1 rgb <1,0.5,0>] } } \
       finish { ambient 0 diffuse 0 emission 1 } }"
  in
  (* u there: 0.75 + atan2(0.2, ...)/(2 pi), about 0.782 *)
  if not (w.r > 0.77 && w.r < 0.8) then Alcotest.failf "whitted u: %g" w.r;
  Scn.color ~eps:1e-4 "mc emission as whitted" (w.r, w.g, w.b) m;
  let w, m =
    both
      "camera { orthographic location <0,0,-5> look_at 0 right 0.001*x up 0.001*y }\n\
       light_source { <1000,0,-1000>, rgb 1 }\n\
       plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n\
       sphere { <2,0,-2>, 0.8 pigment { uv_mapping gradient x color_map { [0 rgbf <1,0,0,1>] [1 rgbf <0,0,1,1>] } } }"
  in
  (* POV-Ray: 0.05524 0 0.23201 (see [shadows]) *)
  Scn.color ~eps:1e-4 "whitted shadow through the uv sphere" (0.05524, 0., 0.23201) w;
  Scn.color ~eps:1e-4 "mc shadow ray as whitted's" (w.r, w.g, w.b) m

let tests =
  ( "uv",
    [
      Alcotest.test_case "sphere" `Quick sphere;
      Alcotest.test_case "box" `Quick box;
      Alcotest.test_case "torus" `Quick torus;
      Alcotest.test_case "mesh" `Quick mesh;
      QCheck_alcotest.to_alcotest range;
      Alcotest.test_case "transforms and forms" `Quick transforms;
      Alcotest.test_case "uv-mapped normals as POV-Ray" `Quick normals;
      Alcotest.test_case "uv-mapped normals: errors, the uv flag" `Quick normal_errors;
      Alcotest.test_case "shadow rays through uv-mapped surfaces" `Quick shadows;
      Alcotest.test_case "mc mode reads uv" `Quick mc;
    ] )
