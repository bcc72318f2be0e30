(* Patterns against POV-Ray 3.7's function { pattern { ... } } values at
   fixed points (read with #debug), and colour maps (pov-facts.md 6). *)
open Camlray

let pts =
  [| Vec3.make 0.25 0.1 0.2; Vec3.make 1. 0.5 0.3; Vec3.make (-0.3) 0.2 0.7; Vec3.make 0.5 0.5 0.5;
     Vec3.make 2.3 0.1 (-1.2); Vec3.make 0.1 0.3 (-0.4) |]

let pov =
  [
    ("radial", Pattern.Radial, [| 0.89261; 0.95361; 0.68556; 0.87500; 0.07653; 0.21100 |]);
    ("onion", Pattern.Onion, [| 0.33541; 0.15758; 0.78740; 0.86603; 0.59615; 0.50990 |]);
    ("planar", Pattern.Planar, [| 0.9; 0.5; 0.8; 0.5; 0.9; 0.7 |]);
    ("spherical", Pattern.Spherical, [| 0.66459; 0.; 0.21260; 0.13397; 0.; 0.49010 |]);
    ("wood", Pattern.Wood, [| 0.53852; 0.23605; 0.72111; 0.58579; 0.60431; 0.63246 |]);
    ("marble", Pattern.Marble, [| 0.5; 0.; 0.6; 1.; 0.59996; 0.2 |]);
    ("leopard", Pattern.Leopard, [| 0.03311; 0.29031; 0.03329; 0.22985; 0.00083; 0. |]);
    ("checker", Pattern.Checker, [| 0.; 1.; 1.; 0.; 0.; 1. |]);
    ("gradient x", Pattern.gradient Vec3.unit_x, [| 0.25; 1.; 0.7; 0.5; 0.3; 0.1 |]);
  ]

let exact () =
  List.iter
    (fun (name, k, expected) ->
      Array.iteri
        (fun i e ->
          Scn.close ~eps:2e-4 (Printf.sprintf "%s at point %d" name i) e
            (Pattern.value (Pattern.make k) pts.(i)))
        expected)
    pov

(* (x, y, z, hexagon, brick) sampled from POV-Ray at random points *)
let blocks =
  [
    (5.447195, 0.883730, -3.997774, 1, 1);
    (-5.581595, 1.914773, -1.404291, 2, 1);
    (-0.215647, 2.413731, 3.914352, 2, 0);
    (3.544956, -3.307926, -2.429032, 2, 0);
    (2.161463, -0.226606, 5.881209, 2, 0);
    (0.708388, -2.129032, -2.396851, 0, 1);
    (5.474252, 2.752052, -3.919590, 1, 0);
    (-0.757065, 2.509429, 4.478348, 1, 0);
    (-0.115358, -0.128256, 4.457965, 0, 0);
    (2.134664, 0.289639, 0.220898, 0, 1);
    (-2.460177, 2.809044, -5.272795, 0, 0);
    (4.684305, 0.428772, -3.011074, 0, 1);
    (5.646987, 3.712031, -2.408964, 2, 1);
    (-0.726943, 2.345753, -3.327018, 1, 1);
    (-2.583107, -0.449899, -5.076645, 0, 0);
    (-1.073826, -2.547827, 0.849579, 2, 1);
  ]

let block_patterns () =
  let v k (x, y, z) = int_of_float (Pattern.value (Pattern.make k) (Vec3.make x y z)) in
  let brick = Pattern.Brick { size = Vec3.make 8. 3. 4.5; mortar = 0.5 } in
  List.iter
    (fun (x, y, z, h, b) ->
      Alcotest.(check int) (Printf.sprintf "hexagon at %g %g %g" x y z) h (v Pattern.Hexagon (x, y, z));
      Alcotest.(check int) (Printf.sprintf "brick at %g %g %g" x y z) b (v brick (x, y, z)))
    blocks

let gradient () =
  let g v p = Pattern.value (Pattern.make (Pattern.gradient v)) p in
  Scn.close ~eps:1e-4 "gradient x at -1.75" 0.25 (g Vec3.unit_x (Vec3.make (-1.75) 0. 0.));
  Scn.close ~eps:1e-3 "gradient <1,1,0> at x=-1.75" 0.763 (g (Vec3.make 1. 1. 0.) (Vec3.make (-1.75) 0. 0.));
  let tri = { (Pattern.make (Pattern.gradient Vec3.unit_x)) with wave = Some Pattern.Triangle } in
  Scn.close "triangle wave" 0.6 (Pattern.value tri (Vec3.make (-0.3) 0. 0.))

(* pigments through the scene language: a plane at z = 1, ambient 1 *)
let pig ?(x = 0) ?(w = 1) p =
  Scn.pixel ~w ~x (Printf.sprintf "plane { z, 1 pigment { %s } finish { ambient 1 diffuse 0 } }" p)

let maps () =
  Scn.color "color_map interpolation" (0.8, 0., 0.2)
    (pig "gradient x color_map { [0.25 rgb <1,0,0>] [0.75 rgb <0,0,1>] } translate -x*0.35");
  Scn.color "below the first entry" (1., 0., 0.)
    (pig "gradient x colour_map { [0.25 rgb <1,0,0>] [0.75 rgb <0,0,1>] } translate -x*0.1");
  Scn.color "checker defaults: blue in the unit cube" (0., 0., 1.) (pig "checker translate <-0.5,-0.5,0.5>");
  Scn.color "checker list" (0., 1., 0.) (pig "checker rgb <1,0,0>, rgb <0,1,0> translate <-0.5,-0.5,0>");
  Scn.color "pigment_map" (0.5, 1., 0.)
    (pig "gradient x pigment_map { [0 checker rgb 0, rgb <1,1,0>] [1 rgb <0,1,0>] } translate <0.5,0.5,0>");
  Scn.color "frequency" (0.4, 0.4, 0.4) (pig "gradient x frequency 2 translate -x*0.2")

let transforms () =
  (* checker scaled by 2: the cell [0,2)^3 is blue, x in [-2,0) green *)
  Scn.color "pattern scale" (0., 0., 1.) (pig "checker scale 2 translate -x*1.5");
  (* a texture written before an object transform moves with the object *)
  let obj order =
    Scn.pixel
      (Printf.sprintf "plane { z, 1 %s finish { ambient 1 diffuse 0 } }"
         (if order then "pigment { checker } translate <0.5,0,0>" else "translate <0.5,0,0> pigment { checker }"))
  in
  (* hit (0,0,1): before -> pattern at (-0.5,0,1) (even: blue); after -> (0,0,1) (odd: green) *)
  Scn.color "texture before transform moves" (0., 0., 1.) (obj true);
  Scn.color "texture after transform stays" (0., 1., 0.) (obj false)

let image_map () =
  let file = Filename.concat (Filename.get_temp_dir_name ()) (Printf.sprintf "camlray-im-%d.png" (Unix.getpid ())) in
  let data = Bytes.of_string "\128\000\255\000\255\000" in
  Image.write_png file { Image.w = 2; h = 1; data };
  let px tr =
    Scn.pixel (Printf.sprintf "plane { z, 1 pigment { image_map { png \"%s\" } translate %s } finish { ambient 1 diffuse 0 } }" file tr)
  in
  (* the image spans [0,1]^2 of the xy plane; PNG values are sRGB-decoded *)
  Scn.color "left texel" (0.21586, 0., 1.) (px "<-0.25, -0.5, 0>");
  Scn.color "right texel, repeated" (0., 1., 0.) (px "<-1.75, -0.5, 0>");
  Sys.remove file

(* normal { PATTERN, BUMP_SIZE }: the comma is optional (POV-Ray reads
   both forms; textures/patterns/gradient.pov uses it) *)
let normal_comma () =
  let amount src =
    let s = Scn.compile (Printf.sprintf "sphere { 0, 1 normal { %s } }" src) in
    match s.objects.(0).texture with
    | { normal = Some n; _ } :: _ -> n.amount
    | _ -> Alcotest.failf "no normal in %S" src
  in
  Scn.close "bumps, 0.5" 0.5 (amount "bumps, 0.5");
  Scn.close "bumps 0.5" 0.5 (amount "bumps 0.5");
  Scn.close "gradient x, 5.6" 5.6 (amount "gradient x, 5.6 scale 0.24")

let tests =
  ( "pattern",
    [
      Alcotest.test_case "exact patterns = POV-Ray" `Quick exact;
      Alcotest.test_case "hexagon and brick = POV-Ray" `Quick block_patterns;
      Alcotest.test_case "gradient and waves" `Quick gradient;
      Alcotest.test_case "maps" `Quick maps;
      Alcotest.test_case "transforms" `Quick transforms;
      Alcotest.test_case "normal bump size after a comma" `Quick normal_comma;
      Alcotest.test_case "image_map" `Quick image_map;
    ] )
