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

let tests =
  ( "pattern",
    [
      Alcotest.test_case "exact patterns = POV-Ray" `Quick exact;
      Alcotest.test_case "gradient and waves" `Quick gradient;
      Alcotest.test_case "maps" `Quick maps;
      Alcotest.test_case "transforms" `Quick transforms;
    ] )
