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

(* Where a map's entries are taken (POV-Ray 3.7's Compute_Pigment and
   ComputeOneTextureColour): at the map's pattern's point, after its
   transformations and warps, whatever the order they and the map were
   written in. The hit is (0, 0, 1); each value worked out by hand, and
   POV-Ray's 1x1 renders of the pigments agree to its 8 bits. *)
let red_y = "gradient y color_map { [0 rgb 0] [1 rgb <1,0,0>] }"

let map_space () =
  (* scale 4 written before the map: the pattern's point (1, 2, 1) / 4;
     gradient x 0.25 blends 3/4 of the first entry, gradient y there
     0.5, and 1/4 blue *)
  Scn.color "a scale before the map moves the entries" (0.375, 0., 0.25)
    (pig (Printf.sprintf "gradient x scale 4 pigment_map { [0 %s] [1 rgb <0,0,1>] } translate <-1, -2, 0>" red_y));
  Scn.color "and after it alike" (0.375, 0., 0.25)
    (pig (Printf.sprintf "gradient x pigment_map { [0 %s] [1 rgb <0,0,1>] } scale 4 translate <-1, -2, 0>" red_y));
  (* repeat x*0.5 offset y*0.25 at (0.7, 0.1, 1): the second copy, x 0.2
     and y 0.1 + 0.25 *)
  Scn.color "entries at the warped point" (0.28, 0., 0.2)
    (pig (Printf.sprintf "gradient x warp { repeat x*0.5 offset y*0.25 } pigment_map { [0 %s] [1 rgb <0,0,1>] } translate <-0.7, -0.1, 0>" red_y));
  (* a nested map's entries: in the inner map's space, inside the outer's:
     (0.25, 0.5, 0.25) / 0.8, gradient y 0.625 *)
  Scn.color "nested maps" (0.46875, 0., 0.25)
    (pig
       (Printf.sprintf
          "gradient x scale 4 pigment_map { [0 gradient x scale 0.8 pigment_map { [0 %s] [1 %s] }] [1 rgb <0,0,1>] } translate <-1, -2, 0>"
          red_y red_y));
  (* a pigment_pattern's own pigment is evaluated in the middle of the
     outer map's: the entries still get the outer's point (1, 0.3, 1);
     the inner gradient x scale 2 gives 0.5 *)
  Scn.color "pigment_pattern: entries at the outer point" (0.15, 0., 0.5)
    (pig
       (Printf.sprintf
          "pigment_pattern { gradient x scale 2 } pigment_map { [0 %s] [1 rgb <0,0,1>] } translate <-1, -0.3, 0>"
          red_y));
  (* a block pattern's pigments follow it *)
  Scn.color "a checker's pigments follow its scale" (0.5, 0., 0.)
    (pig (Printf.sprintf "checker pigment { %s } pigment { rgb 1 } scale 2 translate <-0.5, -1, 0>" red_y));
  (* an average: its transformations move its entries' point *)
  Scn.color "average scaled" (0.25, 0., 0.5)
    (pig (Printf.sprintf "average scale 2 pigment_map { [1 %s] [1 rgb <0,0,1>] } translate <0, -1, 0>" red_y));
  (* texture_map: the same point *)
  Scn.color "texture_map entries scaled before" (0.375, 0., 0.25)
    (Scn.pixel
       (Printf.sprintf
          "plane { z, 1 texture { gradient x scale 4 texture_map { [0 pigment { %s } finish { ambient 1 diffuse 0 }] [1 pigment { rgb <0,0,1> } finish { ambient 1 diffuse 0 }] } translate <-1, -2, 0> } }"
          red_y));
  (* marble handles its turbulence itself: its entries are not moved by
     it (gradient y stays 0.4); a gradient's are *)
  let turb k = pig (Printf.sprintf "%s turbulence 1 pigment_map { [0 %s] [1 %s] } translate <-0.3, -0.4, 0>" k red_y red_y) in
  Scn.color "marble's entries without its turbulence" (0.4, 0., 0.) (turb "marble");
  let c = turb "gradient x" in
  if Float.abs (c.r -. 0.4) < 1e-3 then Alcotest.failf "gradient x turbulence: entries not turbulated (%g)" c.r

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
  (* in the working folder: scenes may read only where they are allowed *)
  let file = Printf.sprintf "camlray-im-%d.png" (Unix.getpid ()) in
  let data = Bytes.of_string "\128\000\255\000\255\000" in
  Image.write_png file { Image.w = 2; h = 1; data };
  let px tr =
    Scn.pixel (Printf.sprintf "plane { z, 1 pigment { image_map { png \"%s\" } translate %s } finish { ambient 1 diffuse 0 } }" file tr)
  in
  (* the image spans [0,1]^2 of the xy plane; PNG values are sRGB-decoded *)
  Scn.color "left texel" (0.21586, 0., 1.) (px "<-0.25, -0.5, 0>");
  Scn.color "right texel, repeated" (0., 1., 0.) (px "<-1.75, -0.5, 0>");
  Sys.remove file

(* a point on the edge between two rows takes the upper row, as POV-Ray's
   map_pos does with its tiny offset ((1 - v) h gave the lower one: every
   fifth row of a 120-row image seen at 0.01 a pixel differed) *)
let image_map_edges () =
  let file = Printf.sprintf "camlray-rows-%d.png" (Unix.getpid ()) in
  (* one column, rows from the top: red, green, blue, white *)
  Image.write_png file { Image.w = 1; h = 4; data = Bytes.of_string "\255\000\000\000\255\000\000\000\255\255\255\255" };
  Fun.protect
    ~finally:(fun () -> Sys.remove file)
    (fun () ->
      let pig =
        match (Scn.compile (Printf.sprintf "plane { z, 1 pigment { image_map { png \"%s\" } } }" file)).objects.(0).texture with
        | { pigment; _ } :: _ -> pigment
        | [] -> Alcotest.fail "no texture"
      in
      let at y = let c = Pigment.eval pig (Vec3.make 0.5 y 0.) in (c.c.r, c.c.g, c.c.b) in
      let rgb = Alcotest.(triple (float 0.) (float 0.) (float 0.)) in
      Alcotest.check rgb "inside the lowest row" (1., 1., 1.) (at 0.1);
      Alcotest.check rgb "on the edge 0.25: the row above (blue)" (0., 0., 1.) (at 0.25);
      Alcotest.check rgb "on the edge 0.5: green" (0., 1., 0.) (at 0.5);
      Alcotest.check rgb "on the edge 0.75: red" (1., 0., 0.) (at 0.75);
      Alcotest.check rgb "on the bottom edge 0: the lowest row" (1., 1., 1.) (at 0.))

(* map_type 5: the torus of major radius 1 about y, columns by the angle
   about y from +x towards +z (POV-Ray's map_pos; drawn planar before);
   a map_type POV-Ray's parser refuses is a located error *)
let image_map_torus () =
  let file = Printf.sprintf "camlray-torus-%d.png" (Unix.getpid ()) in
  (* one row of four columns: red, green, blue, white *)
  Image.write_png file { Image.w = 4; h = 1; data = Bytes.of_string "\255\000\000\000\255\000\000\000\255\255\255\255" };
  Fun.protect
    ~finally:(fun () -> Sys.remove file)
    (fun () ->
      let pig =
        match (Scn.compile (Printf.sprintf "torus { 1, 0.25 pigment { image_map { png \"%s\" map_type 5 } } }" file)).objects.(0).texture with
        | { pigment; _ } :: _ -> pigment
        | [] -> Alcotest.fail "no texture"
      in
      let at x y z = let c = Pigment.eval pig (Vec3.make x y z) in (c.c.r, c.c.g, c.c.b) in
      let rgb = Alcotest.(triple (float 0.) (float 0.) (float 0.)) in
      Alcotest.check rgb "an eighth of a turn: the first column" (1., 0., 0.) (at 0.8 0. 0.8);
      Alcotest.check rgb "a quarter turn, towards +z: the second" (0., 1., 0.) (at 0. 0. 1.25);
      Alcotest.check rgb "five eighths of a turn: the third" (0., 0., 1.) (at (-0.8) 0.1 (-0.8));
      Alcotest.check rgb "seven eighths: the fourth" (1., 1., 1.) (at 0.8 (-0.1) (-0.8));
      let d = Scn.error (Printf.sprintf "plane { z, 1 pigment { image_map { png \"%s\" map_type 3 } } }" file) in
      if not (Scn.contains d.msg "map_type must be 0") then Alcotest.failf "map_type 3: %S" d.msg)

(* image_map's interpolate 2, 3 and 4 as POV-Ray's imageutil.cpp weighs
   the texels (interpolate 3 and 4 were drawn bilinear: POV-Ray's
   textures/pigments/interp.pov 39.4 dB, now identical): a 2 x 2 checker
   of black and white read at (0.375, 0.625), a quarter of a texel past
   the texel centres' grid in x and y; values worked out by hand *)
let image_map_interpolation () =
  let file = Printf.sprintf "camlray-interp-%d.png" (Unix.getpid ()) in
  (* rows from the top: black, white / white, black *)
  Image.write_png file { Image.w = 2; h = 2; data = Bytes.of_string "\000\000\000\255\255\255\255\255\255\000\000\000" };
  Fun.protect
    ~finally:(fun () -> Sys.remove file)
    (fun () ->
      let at n =
        match (Scn.compile (Printf.sprintf "plane { z, 1 pigment { image_map { png \"%s\" interpolate %d } } }" file n)).objects.(0).texture with
        | { pigment; _ } :: _ -> (Pigment.eval pigment (Vec3.make 0.375 0.625 0.)).c.r
        | [] -> Alcotest.fail "no texture"
      in
      (* bilinear: the two white corners, each (3/4)(1/4) *)
      Scn.close ~eps:1e-6 "interpolate 2" 0.375 (at 2);
      (* normalized distance: the white corners at squared distances 5/8
         (weights 8/5 each), the black at 9/8 and 1/8 *)
      Scn.close ~eps:1e-6 "interpolate 4" (3.2 /. ((1. /. 1.125) +. 1.6 +. 1.6 +. 8.)) (at 4);
      (* bicubic: the 4 x 4 texels (a checker repeated), weights by the
         cubic at 1/4 along each axis: 2 (w0 + w2)(w1 + w3) *)
      Scn.close ~eps:1e-6 "interpolate 3" (2. *. (-0.0703125 +. 0.2265625) *. (0.8671875 -. 0.0234375)) (at 3);
      Scn.close "none" 0. (at 0);
      Scn.check_message (Printf.sprintf "plane { z, 1 pigment { image_map { png \"%s\" interpolate 1 } } }" file)
        "interpolate is 2 (bilinear), 3 (bicubic) or 4")

(* hexagon on its cells' edges, as POV-Ray 3.7's function { pattern {
   hexagon } } gives them (read with #debug): corners and sides on z = 0,
   a negative x, an edge at negative z (camlray's nearest-centre rounding
   gave 0 1 1 _ _ 2 at four of them) *)
let hexagon_edges () =
  let f = Scn.float ~prelude:"#declare F = function { pattern { hexagon } }" in
  Scn.check_floats "edges"
    [ 0.; 2.; 2.; 0.; 0.; 0.; 0.; 0. ]
    (List.map f
       [ "F(0.75, 0, 0)"; "F(1, 0, 0)"; "F(1.5, 0, 0)"; "F(2, 0, 0)"; "F(-0.75, 0, 0)"; "F(0.3, 0, -0.866025404)";
         "F(3, 0, 0.5)"; "F(0.25, 0, 0.4330127)" ])

(* POV-Ray 3.7's brick near its mortar's edges (default bricks, values
   from povray 3.7's function { pattern { brick } }): the point moved by
   mortar + 1e-10, a fraction of a cell at most mortar / size is mortar *)
let brick_edges () =
  let f = Scn.float ~prelude:"#declare F = function { pattern { brick } }" in
  let cases =
    [ ("7.5-1e-8, 1, 0", 1.); ("7.5-1.1e-10, 1, 0", 1.); ("7.5-0.9e-10, 1, 0", 0.); ("7.5-1e-11, 1, 0", 0.);
      ("8-0.9e-10, 1, 0", 1.); ("8-1.1e-10, 1, 0", 0.); ("-0.5, 1, 0", 0.); ("-0.5009, 1, 0", 1.);
      ("-24.500000000100002, -4.569819722431236, -0.5000000002", 0.); ("7.4999999998, 9.0, 13.4999999999", 1.);
      ("-16.0000000001, 1.5000000001, -1e-10", 1.); ("-4.5000000001, 3.0000000001, 13.5000000001", 0.);
      ("7.4999999999, 1.4999999999, -4.5", 0.); ("1e-10, 5.4999999999, 6.2499999999", 0.);
      ("24.0000000001, 5.4999999998, -5.0000000001", 0.); ("15.5, 5.4999999999, 2.2500000001", 0.) ]
  in
  Scn.check_floats "brick edges" (List.map snd cases) (List.map (fun (p, _) -> f ("F(" ^ p ^ ")")) cases)

(* an image's file type before its name: png, jpeg and ppm read (by their
   bytes), others refused by name where they are written *)
let image_kinds () =
  let file = Printf.sprintf "camlray-kind-%d.ppm" (Unix.getpid ()) in
  Image.write_ppm file { Image.w = 1; h = 1; data = Bytes.of_string "\255\000\000" };
  Fun.protect
    ~finally:(fun () -> Sys.remove file)
    (fun () ->
      let src kind = Printf.sprintf "plane { z, 1 pigment { image_map { %s \"%s\" } } finish { ambient 1 diffuse 0 } }" kind file in
      Scn.color "ppm keyword" (1., 0., 0.) (Scn.pixel (src "ppm"));
      Scn.color "no keyword" (1., 0., 0.) (Scn.pixel (src ""));
      let d = Scn.error (src "iff") in
      Alcotest.(check (pair int int)) "iff: where" (1, 36) (Camlray_lang.Loc.line d.loc, Camlray_lang.Loc.col d.loc);
      if not (Scn.contains d.msg "iff images are not read") then Alcotest.failf "iff: %S" d.msg;
      let d = Scn.error (Printf.sprintf "plane { z, 1 normal { bump_map { tga \"%s\" } } }" file) in
      if not (Scn.contains d.msg "tga images are not read") then Alcotest.failf "bump_map tga: %S" d.msg)

(* POV-Ray's [filter N, A] and [transmit N, A] in an image_map: the
   filter or transmit of palette entry N (int (N + 0.01)), after and
   before [... all A] in the order written; an image without a palette,
   an entry past the palette's end, or another channel, are located
   errors (interior/media/media3.pov, "unexpected number" before) *)
let image_map_palette () =
  let pal = Printf.sprintf "camlray-pal-%d.png" (Unix.getpid ()) in
  let rgb = Printf.sprintf "camlray-rgb-%d.png" (Unix.getpid ()) in
  (* 2 x 1: entry 1 (40, 50, 60) then entry 0 (10, 20, 30) *)
  Test_image.write_file pal
    (Test_image.hand_png ~before:[ ("PLTE", "\010\020\030\040\050\060") ] ~w:2 ~h:1 ~ct:3 ~depth:8
       (Test_image.zlib_stored "\000\001\000"));
  Image.write_png rgb { Image.w = 2; h = 1; data = Bytes.make 6 '\100' };
  Fun.protect
    ~finally:(fun () -> Sys.remove pal; Sys.remove rgb)
    (fun () ->
      let px items =
        match (Scn.compile (Printf.sprintf "plane { z, 1 pigment { image_map { png \"%s\" %s } } }" pal items)).objects.(0).texture with
        | { pigment = Pigment.Image_map { image; _ }; _ } :: _ ->
            Array.to_list (Array.map (fun (c : Color.rgbft) -> (c.filter, c.transmit)) image.px)
        | _ -> Alcotest.fail "no image_map"
      in
      let ft = Alcotest.(list (pair (float 0.) (float 0.))) in
      Alcotest.check ft "transmit 1, 1: the first pixel" [ (0., 1.); (0., 0.) ] (px "transmit 1, 1");
      Alcotest.check ft "filter 0.995, 0.5 is entry 1" [ (0.5, 0.); (0., 0.) ] (px "filter 0.995, 0.5");
      Alcotest.check ft "in order: all, then one entry" [ (0., 0.3); (0., 1.) ] (px "transmit all 0.3 transmit 0, 1");
      Alcotest.check ft "in order: one entry, then all" [ (0.2, 0.); (0.2, 0.) ] (px "filter 1, 0.9 filter all 0.2");
      let err file items =
        Scn.error (Printf.sprintf "plane { z, 1 pigment { image_map { png \"%s\"\n  %s } } }" file items)
      in
      let located what (d : Camlray_lang.Diag.t) line col sub =
        Alcotest.(check (pair int int)) (what ^ ": where") (line, col) (Camlray_lang.Loc.line d.loc, Camlray_lang.Loc.col d.loc);
        if not (Scn.contains d.msg sub) then Alcotest.failf "%s: message %S does not contain %S" what d.msg sub
      in
      located "no palette" (err rgb "transmit 1, 1") 2 12 "has no palette";
      located "past the end" (err pal "filter 2, 1") 2 10 "palette entry 2 is out of range";
      located "negative" (err pal "filter -2, 1") 2 10 "palette entry -1 is out of range";
      located "a colour channel" (err pal "red all 1") 2 3 "filter or transmit here, not red")

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

(* spiral1, spiral2, quilted, mandel: values worked out by hand from
   POV-Ray's formulas (core/material/pattern.cpp), wrapped by its
   fmod(v, 1.00001) at frequency 1 *)
let spirals () =
  let v ?wave k (x, y, z) =
    let t = Pattern.make k in
    Pattern.value (match wave with Some _ -> { t with wave } | None -> t) (Vec3.make x y z)
  in
  (* spiral1 3 at (1,0,0): r 1, angle pi/2, 0 + 1 + 3 (pi/2) / 2 pi = 1.75;
     1.75 - 1.00001 = 0.74999; triangle: 2 (1 - 0.74999) *)
  Scn.close ~eps:1e-9 "spiral1 3 at (1,0,0)" 0.50002 (v (Pattern.Spiral1 3) (1., 0., 0.));
  (* (0,1,0.1): angle pi/2 + asin 1 = pi: 0.1 + 1 + 1.5 = 2.6 -> 0.59998 *)
  Scn.close ~eps:1e-9 "spiral1 3 at (0,1,0.1)" 0.80004 (v (Pattern.Spiral1 3) (0., 1., 0.1));
  (* (-1,0,0): x < 0, angle 3 pi/2: 1 + 2.25 = 3.25 -> 0.24997 *)
  Scn.close ~eps:1e-9 "spiral1 3 at (-1,0,0)" 0.49994 (v (Pattern.Spiral1 3) (-1., 0., 0.));
  (* on the axis the angle is 0: the value is z *)
  Scn.close ~eps:1e-12 "spiral1 3 on the axis" 0.6 (v (Pattern.Spiral1 3) (0., 0., 0.3));
  Scn.close ~eps:1e-12 "spiral1 3 on the axis, ramp" 0.3 (v ~wave:Pattern.Ramp (Pattern.Spiral1 3) (0., 0., 0.3));
  (* (0.6,0.8,0): angle pi/2 + asin 0.8, 1 + 3 angle / 2 pi = 2.1927509 *)
  Scn.close ~eps:1e-6 "spiral1 3 at (0.6,0.8,0), ramp" 0.1927309
    (v ~wave:Pattern.Ramp (Pattern.Spiral1 3) (0.6, 0.8, 0.));
  (* spiral2 2 there: tri(1 + 2 angle / 2 pi = 1.7951672) + tri(r = 1)
     = 2 (1 - 0.7951672) + 0 = 0.4096655 *)
  Scn.close ~eps:1e-6 "spiral2 2 at (0.6,0.8,0), ramp" 0.4096655
    (v ~wave:Pattern.Ramp (Pattern.Spiral2 2) (0.6, 0.8, 0.));
  Scn.close ~eps:1e-6 "spiral2 2 at (0.6,0.8,0)" 0.8193311 (v (Pattern.Spiral2 2) (0.6, 0.8, 0.))

let quilted () =
  let q c0 c1 (x, y, z) = Pattern.value (Pattern.make (Pattern.Quilted { c0; c1 })) (Vec3.make x y z) in
  (* the cell's centre: no offset *)
  Scn.close ~eps:1e-12 "centre" 0. (q 1. 1. (0.5, 0.5, 0.5));
  Scn.close ~eps:1e-12 "centre of another cell" 0. (q 1. 1. (-1.5, 2.5, 0.5));
  (* a corner: offset (-0.5,-0.5,-0.5), t = sqrt 0.75; controls 1, 1:
     1 - (1-t)^3 = 0.9975951, / sqrt 0.75 = 1.1519237; times 0.5 *)
  Scn.close ~eps:1e-6 "corner, controls 1 1" 0.5759618 (q 1. 1. (0., 0., 0.));
  (* controls 0, 0: t^3 / sqrt 0.75 = 0.75; times 0.5 *)
  Scn.close ~eps:1e-6 "corner, controls 0 0" 0.375 (q 0. 0. (2., -1., 3.));
  (* a face centre: t = 0.5, 1 - 0.125 = 0.875, / sqrt 0.75 = 1.0103630;
     times 0.5, over 3 *)
  Scn.close ~eps:1e-6 "face centre" 0.1683938 (q 1. 1. (0.5, 0.5, 0.));
  let s = Scn.compile "sphere { 0, 1 pigment { quilted control0 0.3 control1 -2 } }" in
  match s.objects.(0).texture with
  | { pigment = Pigment.Map { pattern; _ }; _ } :: _ ->
      Scn.close ~eps:0. "quilted: frequency 0 (no wrapping)" 0. pattern.frequency;
      (* POV-Ray keeps the controls in single precision *)
      if pattern.kind <> Pattern.Quilted { c0 = Floats.single 0.3; c1 = -2. } then
        Alcotest.fail "quilted controls"
  | _ -> Alcotest.fail "no quilted pigment"

let mandel () =
  let m ?(exponent = 2) ?(interior = 0) n (x, y) =
    Pattern.value
      (Pattern.make (Pattern.Mandel { (Pattern.mandel n) with exponent; interior }))
      (Vec3.make x y 0.)
  in
  (* inside the set: the interior shade, 1 by default (not wrapped: 1 <
     1.00001) *)
  Scn.close ~eps:0. "inside (0,0)" 1. (m 10 (0., 0.));
  Scn.close ~eps:0. "inside (-1,0)" 1. (m 10 (-1., 0.));
  (* interior 1: the least |z| met; 0 -> -1 -> 0 ... meets 0 *)
  Scn.close ~eps:0. "inside, interior 1" 0. (m ~interior:1 10 (-1., 0.));
  (* c = 3: 9 + 3 = 12 escapes at iteration 0 *)
  Scn.close ~eps:0. "escapes at once" 0. (m 10 (3., 0.));
  (* c = 1: 2 (|z|^2 = 4, not beyond), then 5: iteration 1 of 10 *)
  Scn.close ~eps:1e-12 "c = 1" 0.1 (m 10 (1., 0.));
  (* c = 0.5: 0.75, 1.0625, 1.6289, 3.1533: iteration 3 of 10 *)
  Scn.close ~eps:1e-12 "c = 0.5" 0.3 (m 10 (0.5, 0.));
  (* exponent 3 at 1: 2, then 9 *)
  Scn.close ~eps:1e-12 "exponent 3" 0.1 (m ~exponent:3 10 (1., 0.));
  (* the binomial sum: i^5 = i, so c = i gives 2i then 33i; i^7 = -i, so
     c = i cycles 0, i, 0 ... inside *)
  Scn.close ~eps:1e-12 "exponent 5 at i" 0.1 (m ~exponent:5 10 (0., 1.));
  Scn.close ~eps:0. "exponent 7 at i" 1. (m ~exponent:7 10 (0., 1.));
  (* the built-in map: 0.03 lies between magenta (0.015) and cyan (0.1) *)
  Scn.color "built-in map, c = 0.5" (0.82353, 0.17647, 1.) (pig "mandel 100 translate -x*0.5");
  Scn.color "built-in map, inside" (0., 1., 1.) (pig "mandel 100");
  Scn.color "built-in map, escaping at once" (0., 0., 0.) (pig "mandel 100 translate -x*3");
  (* only exponent 2 has it: the others are black to white *)
  Scn.color "exponent 3: black to white" (1., 1., 1.) (pig "mandel 10 exponent 3");
  let grey = "color_map { [0 rgb 0] [1 rgb 1] }" in
  Scn.color "interior 0, 0.5" (0.5, 0.5, 0.5) (pig ("mandel 10 interior 0, 0.5 exterior 0 0.2 " ^ grey));
  Scn.color "exterior 0 0.2" (0.2, 0.2, 0.2) (pig ("mandel 10 interior 0, 0.5 exterior 0 0.2 translate -x*3 " ^ grey))

let pattern_errors () =
  Scn.check_message "sphere { 0, 1 pigment { bozo control0 0.5 } }" "control0 can only be used with quilted";
  Scn.check_message "sphere { 0, 1 pigment { spiral1 2 exponent 3 } }" "exponent";
  Scn.check_message "sphere { 0, 1 pigment { mandel 10 interior 7, 1 } }" "interior types go from 0 to 6";
  Scn.check_message "sphere { 0, 1 pigment { mandel 0 } }" "at least 1 iteration"

(* function { ... } as a pattern, built through the scene language; the
   expected values are POV-Ray 3.7's function { pattern { function {
   x*x + y } ... } } at the same points (read with #debug): above 1 the
   value is taken mod 1 (1 itself stays), below 0 the frequency step
   takes it mod 1.00001 then adds 1; at frequency 0 it is v - floor v *)
(* the pattern of the first object's pigment *)
let pattern_of (s : Scene.t) what =
  match s.objects.(0).texture with
  | { pigment = Pigment.Map { pattern; _ }; _ } :: _ -> pattern
  | _ -> Alcotest.failf "no pattern pigment in %s" what

let fn_pattern src = pattern_of (Scn.compile (Printf.sprintf "sphere { 0, 1 pigment { %s } }" src)) (Printf.sprintf "%S" src)

(* minor words over 1000 evaluations of [p] at (step i, y, z), after one
   at [prime] (which makes the domain's scratch) *)
let words_over_1000 ?(prime = (0.3, 0.2, 0.1)) ?(step = 0.001) ~y ~z p =
  let q = Vec3.m () and w = Pattern.work () in
  let px, py, pz = prime in
  Vec3.set q px py pz;
  Pattern.eval_m p q w;
  let before = Gc.minor_words () in
  for i = 1 to 1000 do
    Vec3.set q (step *. float_of_int i) y z;
    Pattern.eval_m p q w
  done;
  Gc.minor_words () -. before

(* boxed, cylindrical, pigment_pattern: the values POV-Ray 3.7 prints
   for function { pattern { ... } } at the same points *)
let shape_patterns () =
  let pts = [ (0.3, 0.5, -0.2); (1.5, 0.2, 0.1); (-0.7, -0.1, 0.6); (0.2, 3., 0.3) ] in
  List.iter
    (fun (src, expected) ->
      let p = fn_pattern src in
      List.iter2
        (fun (x, y, z) e ->
          Scn.close ~eps:1e-6 (Printf.sprintf "%s at (%g, %g, %g)" src x y z) e (Pattern.value p (Vec3.make x y z)))
        pts expected)
    [
      ("boxed", [ 0.5; 0.; 0.3; 0. ]);
      ("cylindrical", [ 0.639445; 0.; 0.078046; 0.639445 ]);
      ("pigment_pattern { checker rgb 1, rgb 0.3 }", [ 0.3; 0.3; 1.; 0.3 ]);
      ("pigment_pattern { gradient x color_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] } }",
       [ 0.2421; 0.2055; 0.2421; 0.2604 ]);
      ("pigment_pattern { rgb 1 }", [ 1.; 1.; 1.; 1. ]);
      ("pigment_pattern { rgb 2 }", [ 0.99999; 0.99999; 0.99999; 0.99999 ]);
      ("pigment_pattern { rgb -1 }", [ 0.; 0.; 0.; 0. ]);
    ];
  (* gradient wraps itself above 1, onion always, before the frequency
     step's fmod(v, 1.00001); radial is 0.25 + (atan2(x, z) + pi) / 2 pi,
     0.25 on the axis *)
  let at src pts expected =
    let p = fn_pattern src in
    List.iter2
      (fun (x, y, z) e ->
        Scn.close ~eps:1e-7 (Printf.sprintf "%s at (%g, %g, %g)" src x y z) e (Pattern.value p (Vec3.make x y z)))
      pts expected
  in
  let xs = [ (1.5, 0., 0.); (10.5, 0., 0.); (2., 0., 0.); (1., 0., 0.); (-3.3, 0., 0.) ] in
  at "gradient x" xs [ 0.5; 0.5; 0.; 1.; 0.70003 ];
  at "gradient x phase 0.2" xs [ 0.7; 0.7; 0.2; 0.19999; 0.90003 ];
  at "gradient -x" xs [ 0.50001; 0.5001; 0.00001; 0.; 0.3 ];
  at "onion" xs [ 0.5; 0.5; 0.; 0.; 0.3 ];
  at "onion frequency 2" xs [ 1.; 1.; 0.; 0.; 0.6 ];
  at "radial" [ (1.5, 0., 0.); (0.3, 0., -0.4); (0.01, 1., -0.9); (0.0005, 1., 0.0002) ]
    [ 1.; 0.1475736; 0.2482217; 0.25 ];
  at "radial frequency 3 sine_wave" [ (0.3, 0., -0.4); (-1., 0., -0.2) ] [ 0.6760882; 0.7791144 ]

(* slope_map: heights by Hermite cubics between the entries *)
let slope_map () =
  let m l = Float.Array.of_list (List.concat_map (fun (v, h, s) -> [ v; h; s ]) l) in
  let identity = m [ (0., 0., 1.); (1., 1., 1.) ] in
  List.iter (fun v -> Scn.close ~eps:1e-12 "the default map is the identity" v (Normal.slope_height identity v))
    [ 0.; 0.3; 0.77; 1. ];
  let smooth = m [ (0., 0., 0.); (1., 1., 0.) ] in
  Scn.close ~eps:1e-12 "flat ends: 3t^2 - 2t^3 at 0.25" 0.15625 (Normal.slope_height smooth 0.25);
  Scn.close ~eps:1e-12 "flat ends at 0.5" 0.5 (Normal.slope_height smooth 0.5);
  let three = m [ (0.2, 0.5, 0.); (0.6, 1., 2.); (0.8, 0., 0.) ] in
  Scn.close "below the first entry: its height" 0.5 (Normal.slope_height three 0.1);
  Scn.close "past the last: its height" 0. (Normal.slope_height three 0.95);
  (* between 0.6 and 0.8 at t = 0.5: h0 1, s0 2, h1 0, s1 0:
     t^3 (2 + 2) - t^2 (4 + 3) + 2t + 1 = 0.5 - 1.75 + 1 + 1 = 0.75 *)
  Scn.close ~eps:1e-12 "between entries" 0.75 (Normal.slope_height three 0.7);
  Scn.close ~eps:1e-12 "at an entry" 1. (Normal.slope_height three 0.6);
  Scn.check_message "sphere { 0, 1 normal { gradient x slope_map { [0.5 <0, 1>] [0.2 <1, 0>] } } }"
    "slope_map entries must come in order of value (0.2 after 0.5)"

(* warps: the points POV-Ray 3.7's warps give, read back through
   pigment functions whose colour is the warped coordinate (single
   precision there: 1e-5) *)
(* each warp's mapped point, read through three patterns (x, y and z,
   each shifted into [0, 1]) with the pigment's transformations, against
   the values POV-Ray's pigment functions give *)
let check_warped ~eps pts cases =
  List.iter
    (fun (w, expected) ->
      let coord c =
        let s = Scn.compile (Printf.sprintf "sphere { 0, 1 pigment { function { (%s + 50) / 100 } %s } }" c w) in
        match s.objects.(0).texture with
        | { pigment = Pigment.Map { pattern; xform; _ }; _ } :: _ -> (pattern, xform)
        | _ -> Alcotest.fail "no pattern"
      in
      let px = coord "x" and py = coord "y" and pz = coord "z" in
      List.iter2
        (fun (x, y, z) (ex, ey, ez) ->
          let at (p, xf) = (Pattern.value p (Transform.inv_point xf (Vec3.make x y z)) *. 100.) -. 50. in
          Scn.check_floats ~eps (Printf.sprintf "%s at (%g, %g, %g)" w x y z) [ ex; ey; ez ] [ at px; at py; at pz ])
        pts expected)
    cases

let warps () =
  let pts = [ (0.3, 0.2, 0.1); (1.7, 0.5, -0.2); (2.6, -0.4, 0.3); (-0.9, 1.2, 0.8); (-3.1, 0.1, -0.6);
              (0.6, 0.7, 0.0); (0.1, 0.05, 0.0); (1.2, -1.9, 0.4) ] in
  check_warped ~eps:1e-5 pts
    [
      ("warp { repeat x*2 }",
       [ (0.3, 0.2, 0.1); (1.7, 0.5, -0.2); (0.6, -0.4, 0.3); (1.1, 1.2, 0.8); (0.9, 0.1, -0.6); (0.6, 0.7, 0.0); (0.1, 0.05, 0.0); (1.2, -1.9, 0.4) ]);
      ("warp { repeat x*2 offset <0.25, 0.5, 1> }",
       [ (0.3, 0.2, 0.1); (1.7, 0.5, -0.2); (0.85, 0.1, 1.3); (0.85, 0.7, -0.2); (0.4, -0.9, -2.6); (0.6, 0.7, 0.0); (0.1, 0.05, 0.0); (1.2, -1.9, 0.4) ]);
      ("warp { repeat x*2 flip y }",
       [ (0.3, 0.2, 0.1); (1.7, 0.5, -0.2); (0.6, 0.4, 0.3); (1.1, -1.2, 0.8); (0.9, 0.1, -0.6); (0.6, 0.7, 0.0); (0.1, 0.05, 0.0); (1.2, -1.9, 0.4) ]);
      ("warp { repeat x*2 flip x }",
       [ (0.3, 0.2, 0.1); (1.7, 0.5, -0.2); (1.4, -0.4, 0.3); (0.9, 1.2, 0.8); (0.9, 0.1, -0.6); (0.6, 0.7, 0.0); (0.1, 0.05, 0.0); (1.2, -1.9, 0.4) ]);
      ("warp { repeat y*1.5 flip <1,0,1> offset z*0.3 }",
       [ (0.3, 0.2, 0.1); (1.7, 0.5, -0.2); (-2.6, 1.1, -0.6); (-0.9, 1.2, 0.8); (-3.1, 0.1, -0.6); (0.6, 0.7, 0.0); (0.1, 0.05, 0.0); (1.2, 1.1, -0.2) ]);
      ("warp { repeat -x*2 }",
       [ (-1.7, 0.2, 0.1); (-0.3, 0.5, -0.2); (-1.4, -0.4, 0.3); (-0.9, 1.2, 0.8); (-1.1, 0.1, -0.6); (-1.4, 0.7, 0.0); (-1.9, 0.05, 0.0); (-0.8, -1.9, 0.4) ]);
      ("warp { black_hole <0,0,0>, 1 }",
       [ (0.4175, 0.27834, 0.13916); (1.7, 0.5, -0.2); (2.6, -0.4, 0.3); (-0.9, 1.2, 0.8); (-3.1, 0.1, -0.6); (0.60365, 0.70426, 0.0); (0.17889, 0.08944, 0.0); (1.2, -1.9, 0.4) ]);
      ("warp { black_hole <0.5,0,0>, 2 strength 0.5 falloff 3 }",
       [ (0.23859, 0.26141, 0.13071); (1.72408, 0.51003, -0.20401); (2.6, -0.4, 0.3); (-0.9, 1.2, 0.8); (-3.1, 0.1, -0.6); (0.6135, 0.79455, 0.0); (-0.0018, 0.06273, 0.0); (1.2, -1.9, 0.4) ]);
      ("warp { black_hole <0,0,0>, 1 inverse }",
       [ (0.1825, 0.12167, 0.06083); (1.7, 0.5, -0.2); (2.6, -0.4, 0.3); (-0.9, 1.2, 0.8); (-3.1, 0.1, -0.6); (0.59634, 0.69574, 0.0); (0.02111, 0.01056, 0.0); (1.2, -1.9, 0.4) ]);
      ("warp { black_hole <0,0,0>, 0.5 repeat <2, 1.5, 0> }",
       [ (0.28733, 0.181, 0.10633); (1.7, 0.5, -0.2); (2.6, -0.4, 0.3); (-0.9, 1.2, 0.8); (-3.1, 0.1, -0.6); (0.63056, 0.76112, 0.0); (0.1, 0.05, 0.0); (1.2, -1.9, 0.4) ]);
      ("warp { repeat x*2 } scale 2 warp { black_hole 0, 1 }",
       [ (0.20875, 0.13916, 0.06958); (0.85, 0.25, -0.1); (1.3, -0.2, 0.15); (1.55, 0.6, 0.4); (0.45, 0.05, -0.3); (0.30183, 0.35213, 0.0); (0.08944, 0.04472, 0.0); (0.6, -0.95, 0.2) ]);
    ];
  Scn.check_message "sphere { 0, 1 pigment { bozo warp { repeat <1, 1, 0> } } }" "repeat needs a vector along one axis";
  Scn.check_message "sphere { 0, 1 pigment { bozo warp { black_hole 0, 0 } } }" "a black hole's radius must be positive"

(* the mapping warps: the points POV-Ray 3.7 gives, read back as for
   [warps] (its 5 printed decimals and single precision: 2e-5) *)
let mapping_warps () =
  let pts = [ (0.3, 0.2, 0.1); (1.7, 0.5, -0.2); (2.6, -0.4, 0.3); (-0.9, 1.2, 0.8); (-3.1, 0.1, -0.6);
              (0.6, 0.7, 0.0); (0.1, 0.05, 0.0); (1.2, -1.9, 0.4) ] in
  check_warped ~eps:2e-5 pts
    [
      ("warp { spherical }",
       [ (0.05121, 0.67951, 0.37417); (0.98136, 0.59046, 1.78326); (0.01828, 0.45173, 2.64764); (0.38435, 0.74945, 1.7); (0.53043, 0.51008, 3.15911); (0., 0.77444, 0.92195); (0., 0.64759, 0.1118); (0.05121, 0.18696, 2.28254) ]);
      ("warp { spherical orientation y dist_exp 0.5 }",
       [ (0.03132, -0.37417, 0.41565); (1.3105, -1.78325, 0.7885); (0.02975, -2.64764, 0.73503); (0.50113, -1.7, 0.97716); (0.94278, -3.15911, 0.9066); (0., -0.92196, 0.7436); (0., -0.1118, 0.21653); (0.07737, -2.28254, 0.28247) ]);
      ("warp { cylindrical }",
       [ (0.05121, 0.2, 0.31623); (0.98136, 0.5, 1.71173); (0.01828, -0.4, 2.61725); (0.38435, 1.2, 1.20416); (0.53043, 0.1, 3.15753); (0., 0.7, 0.6); (0., 0.05, 0.1); (0.05121, -1.9, 1.26491) ]);
      ("warp { cylindrical orientation x dist_exp 1 }",
       [ (0.31623, 0.2, -0.01619); (1.71173, 0.5, -1.67982); (2.61725, -0.4, -0.04785); (1.20416, 1.2, -0.46282); (3.15753, 0.1, -1.67484); (0.6, 0.7, 0.); (0.1, 0.05, 0.); (1.26491, -1.9, -0.06477) ]);
      ("warp { toroidal major_radius 0.5 }",
       [ (0.05121, 0.86827, 0.27161); (0.98136, 0.56229, 1.31083); (0.01828, 0.47028, 2.1547); (0.38435, 0.66555, 1.39135); (0.53043, 0.50598, 2.65941); (0., 0.72742, 0.70711); (0., 0.98021, 0.40311); (0.05121, 0.31092, 2.04819) ]);
      ("warp { toroidal orientation y dist_exp 2 major_radius 1.5 }",
       [ (0.07381, -1.20055, 1.40292); (0.28933, -0.54298, 0.20233); (0.02575, -1.1867, 0.62707); (0.58711, -1.23593, 1.20441); (1.46261, -1.66054, 1.40515); (0., -1.14017, 1.16323); (0., -1.40089, 1.95135); (0.18769, -1.91449, 0.8445) ]);
      ("warp { planar }",
       [ (0.3, 0.2, 0.); (1.7, 0.5, 0.); (2.6, -0.4, 0.); (-0.9, 1.2, 0.); (-3.1, 0.1, 0.); (0.6, 0.7, 0.); (0.1, 0.05, 0.); (1.2, -1.9, 0.) ]);
      ("warp { planar y, 0.25 }",
       [ (0.3, -0.25, 0.2); (1.7, -0.25, 0.5); (2.6, -0.25, -0.4); (-0.9, -0.25, 1.2); (-3.1, -0.25, 0.1); (0.6, -0.25, 0.7); (0.1, -0.25, 0.05); (1.2, -0.25, -1.9) ]);
      ("warp { planar <1,1.,0>, 0.25 }",
       [ (0.38891, -0.03535, -0.07071); (1.37886, 0.17678, -0.84853); (2.01526, -0.45962, -2.12132); (-0.45962, 0.67175, 1.48492); (-2.01525, -0.10607, 2.26274); (0.60104, 0.3182, 0.07071); (0.24748, -0.14142, -0.03535); (1.02531, -1.52028, -2.19203) ]);
      ("scale 2 warp { cylindrical orientation z }",
       [ (0.02561, 0.1, 0.15811); (0.49068, 0.25, 0.85586); (0.00914, -0.2, 1.30863); (0.19218, 0.6, 0.60208); (0.26522, 0.05, 1.57877); (0., 0.35, 0.3); (0., 0.025, 0.05); (0.02561, -0.95, 0.63245) ]);
      ("warp { spherical orientation -x }",
       [ (-0.37417, -0.67951, 0.05121); (-1.78325, -0.59046, 0.98136); (-2.64764, -0.45173, 0.01828); (-1.7, -0.74945, 0.38435); (-3.15911, -0.51008, 0.53043); (-0.92196, -0.77444, 0.); (-0.1118, -0.64758, 0.); (-2.28254, -0.18696, 0.05121) ]);
    ];
  (* the centre (and the axis, for the cylinder and torus) stays put *)
  let centre w =
    let s = Scn.compile (Printf.sprintf "sphere { 0, 1 pigment { function { (y + 50) / 100 } %s } }" w) in
    match s.objects.(0).texture with
    | { pigment = Pigment.Map { pattern; _ }; _ } :: _ -> (Pattern.value pattern (Vec3.make 0. 0.3 0.) *. 100.) -. 50.
    | _ -> Alcotest.fail "no pattern"
  in
  Scn.close ~eps:2e-5 "cylindrical on its axis" 0.3 (centre "warp { cylindrical }");
  Scn.close ~eps:2e-5 "toroidal on its axis" 0.3 (centre "warp { toroidal }");
  (* evaluated with nothing allocated *)
  let s =
    Scn.compile
      "sphere { 0, 1 pigment { gradient x warp { planar <1,1,0>, 0.2 } warp { spherical orientation y dist_exp 0.5 } \
       warp { cylindrical orientation x dist_exp 1.5 } warp { toroidal major_radius 0.5 } } }"
  in
  let words = words_over_1000 ~y:0.2 ~z:(-0.3) (pattern_of s "the scene") in
  if words > 0. then Alcotest.failf "%.0f words for 1000 evaluations through mapping warps" words;
  Scn.check_message "sphere { 0, 1 pigment { bozo warp { spherical orientation 0 } } }"
    "a mapping warp's orientation cannot be <0,0,0>";
  Scn.check_message "sphere { 0, 1 pigment { bozo warp { planar <0,0,0>, 1 } } }"
    "a mapping warp's orientation cannot be <0,0,0>"

(* julia: the values POV-Ray prints through pigment functions *)
let julia () =
  let pts = [ (0.1, 0.2, 0.); (0.5, -0.3, 0.); (-0.7, 0.1, 0.4); (1.2, 0.9, 0.); (0., 0., 0.); (-0.2, -0.6, 0.) ] in
  List.iter
    (fun (src, expected) ->
      let p = fn_pattern src in
      List.iter2
        (fun (x, y, z) e -> Scn.close ~eps:1e-6 (Printf.sprintf "%s at (%g, %g, %g)" src x y z) e (Pattern.value p (Vec3.make x y z)))
        pts expected)
    [
      ("julia <0.353, 0.288>, 30", [ 1.000000; 0.200000; 0.100000; 0.000000; 1.000000; 1.000000 ]);
      ("julia <-0.4, 0.6>, 50 interior 1, 1", [ 0.260000; 0.205297; 0.960000; 0.000000; 0.500000; 0.060000 ]);
      ("julia <0.353, 0.288>, 30 exponent 3 exterior 2, 0.5", [ 1.000000; 1.000000; 1.000000; 0.582500; 1.000000; 1.000000 ]);
      ("julia <0.2, 0.5>, 20 interior 6, 0.3 exterior 6, 0.2", [ 0.065386; 0.474810; 0.445753; 0.557297; 0.057603; 0.109655 ]);
    ]

(* mandel and julia against the plain iteration, POV-Ray's as written
   (pow for every power of the general exponent, 0 and 1 too): the same
   value to the last bit. The shading read here (iterations / max, a^2
   or b^2 when escaped; |z|, a^2 or b^2 inside; scaled into [0, 1)) is
   the value itself, frequency 1 leaving it as it is. *)
let fractal_reference ~mandel ~cr ~ci (f : Pattern.fractal) x y =
  let cx = if mandel then x else cr and cy = if mandel then y else ci in
  let e = f.exponent in
  let rec binomial k = if k = 0 then 1 else binomial (k - 1) * (e - k + 1) / k in
  let signed k = float_of_int (if k land 2 <> 0 then -binomial k else binomial k) in
  let pw x k = Float.pow x (float_of_int k) in
  let a = ref x and b = ref y and m2 = ref ((x *. x) +. (y *. y)) in
  let escaped = ref None and n = ref 0 in
  while !escaped = None && !n < f.iterations do
    let a0 = !a and b0 = !b in
    let a2 = a0 *. a0 and b2 = b0 *. b0 in
    (match e with
    | 2 -> b := (2. *. a0 *. b0) +. cy; a := a2 -. b2 +. cx
    | 3 -> b := (3. *. a2 *. b0) -. (b2 *. b0) +. cy; a := (a2 *. a0) -. (3. *. a0 *. b2) +. cx
    | 4 ->
        b := (4. *. ((a2 *. a0 *. b0) -. (a0 *. b2 *. b0))) +. cy;
        a := (a2 *. a2) -. (6. *. a2 *. b2) +. (b2 *. b2) +. cx
    | _ ->
        let re = ref (pw a0 e) and im = ref 0. in
        for k = 1 to e / 2 do re := !re +. (signed (2 * k) *. pw a0 (e - (2 * k)) *. pw b0 (2 * k)) done;
        for k = 0 to (e - 1) / 2 do im := !im +. (signed ((2 * k) + 1) *. pw a0 (e - (2 * k) - 1) *. pw b0 ((2 * k) + 1)) done;
        a := !re +. cx;
        b := !im +. cy);
    let d2 = (!a *. !a) +. (!b *. !b) in
    if d2 < !m2 then m2 := d2;
    if d2 > 4. then escaped := Some !n else incr n
  done;
  match (!escaped, f.exterior, f.interior) with
  | Some n, 1, _ -> float_of_int n /. float_of_int f.iterations
  | Some _, 4, _ -> !a *. !a *. f.efactor
  | Some _, _, _ -> !b *. !b *. f.efactor
  | None, _, 1 -> Float.sqrt !m2 *. f.ifactor
  | None, _, 4 -> !a *. !a *. f.ifactor
  | None, _, _ -> !b *. !b *. f.ifactor

let fractal_props =
  let open QCheck in
  let gen =
    Gen.(
      let coord = float_range (-2.) 2. in
      tup4 (tup3 bool (float_range (-1.) 1.) (float_range (-1.) 1.))
        (tup4 (oneof_list [ 2; 3; 4; 5; 6; 7; 9; 16; 33 ]) (int_range 1 60) (oneof_list [ 1; 4; 5 ])
           (oneof_list [ 1; 4; 5 ]))
        coord coord)
  in
  let print ((mandel, cr, ci), (e, n, t, u), x, y) =
    Printf.sprintf "%s exponent %d, %d iterations, interior %d, exterior %d at (%h, %h)"
      (if mandel then "mandel" else Printf.sprintf "julia <%h, %h>" cr ci) e n t u x y
  in
  [
    Test.make ~name:"mandel and julia = the plain iteration, to the bit" ~count:20000 (make ~print gen)
      (fun ((mandel, cr, ci), (exponent, iterations, interior, exterior), x, y) ->
        (* inside, |z| <= 2 and a^2, b^2 <= 4; escaped, |z| < 3^33 + 3:
           scaled below 1 *)
        let ifactor = if interior = 1 then 0.25 else 0.2 and efactor = if exterior = 1 then 1. else 1e-40 in
        let f = { (Pattern.mandel iterations) with exponent; interior; ifactor; exterior; efactor } in
        let kind = if mandel then Pattern.Mandel f else Pattern.Julia { cr; ci; fractal = f } in
        let got = Pattern.value (Pattern.make kind) (Vec3.make x y 0.) in
        let want = fractal_reference ~mandel ~cr ~ci f x y in
        Int64.equal (Int64.bits_of_float got) (Int64.bits_of_float want)
        || Test.fail_reportf "pattern %h, plain iteration %h" got want);
  ]

(* magnet 1 and 2, mandel and julia: the values POV-Ray prints through
   pigment functions; nothing allocated *)
let magnet () =
  let pts = [ (0.1, 0.2, 0.); (0.5, -0.3, 0.); (-0.7, 0.1, 0.); (1.2, 0.9, 0.); (0., 0., 0.); (-0.2, -0.6, 0.);
              (1.5, 0.2, 0.); (2.5, -1., 0.) ] in
  List.iter
    (fun (src, expected) ->
      let p = fn_pattern src in
      List.iter2
        (fun (x, y, z) e -> Scn.close ~eps:1e-6 (Printf.sprintf "%s at (%g, %g, %g)" src x y z) e (Pattern.value p (Vec3.make x y z)))
        pts expected)
    [
      ("magnet 1 mandel 50", [ 1.000000; 1.000000; 0.080000; 1.000000; 1.000000; 1.000000; 1.000000; 0.280000 ]);
      ("magnet 2 mandel 50", [ 1.000000; 1.000000; 0.040000; 0.120000; 0.200000; 1.000000; 0.420000; 0.040000 ]);
      ("magnet 1 julia <0.5, 0.3>, 30", [ 1.000000; 1.000000; 1.000000; 1.000000; 1.000000; 1.000000; 0.133333; 1.000000 ]);
      ("magnet 2 julia <0.5, 0.3>, 30", [ 1.000000; 1.000000; 1.000000; 0.100000; 1.000000; 1.000000; 0.066667; 1.000000 ]);
      ("magnet 1 mandel 50 interior 1, 1", [ 0.232877; 0.145299; 0.080000; 0.074789; 0.250000; 0.135259; 0.002234; 0.280000 ]);
    ];
  let p = fn_pattern "magnet 2 mandel 50 interior 1, 1" in
  Alcotest.(check (float 0.)) "words over 1000 evaluations" 0. (words_over_1000 ~prime:(0.3, 0.2, 0.) ~y:0.2 ~z:0. p)

(* slope: the values POV-Ray renders on a unit sphere (orthographic,
   16-bit, decoded), at known normals *)
let slope () =
  let v src (nx, ny, nz) (px, py, pz) =
    let p = fn_pattern src in
    let n = Vec3.m () in
    let l = Float.sqrt ((nx *. nx) +. (ny *. ny) +. (nz *. nz)) in
    Vec3.set n (nx /. l) (ny /. l) (nz /. l);
    Pattern.set_normal n;
    let q = Vec3.m () in
    Vec3.set q px py pz;
    Pattern.eval_at p Transform.identity q (Pattern.work ())
  in
  let r = 0.762 in
  let z = -.Float.sqrt (1. -. (r *. r)) in
  Scn.close ~eps:1e-9 "slope y, facing the camera" 0.5 (v "slope y" (0., 0., -1.) (0., 0., -1.));
  (* 0.5 + asin(0.762) / pi = 0.77574; POV-Ray's pixel decodes to 0.7758 *)
  Scn.close ~eps:1e-4 "slope y at 0.762 up" 0.77574 (v "slope y" (0., r, z) (0., r, z));
  Scn.close ~eps:1e-4 "slope y at 0.762 down" 0.22426 (v "slope y" (0., -.r, z) (0., -.r, z));
  Scn.close ~eps:1e-4 "slope { y, 0.2, 0.8 }" 0.95957 (v "slope { y, 0.2, 0.8 }" (0., r, z) (0., r, z));
  (* with altitude, weights 3:1: (3 s + a) / 4 *)
  Scn.close ~eps:1e-4 "slope { y*3 altitude y }" 0.77231 (v "slope { y*3 altitude y }" (0., r, z) (0., r, z));
  Scn.close ~eps:1e-4 "slope { y altitude y, -1, 1 }" 0.82834 (v "slope { y altitude y, -1, 1 }" (0., r, z) (0., r, z));
  Scn.check_message "sphere { 0, 1 pigment { slope { 0 } } }" "cannot be <0,0,0>";
  Scn.check_message "sphere { 0, 1 pigment { slope { y, 0.5, 0.5 } } }" "two different ends"

(* crackle's parameters: relations between them (POV-Ray's values
   themselves are in test_noise's pov_patterns) *)
let crackle_params () =
  let v src (x, y, z) = Pattern.value (fn_pattern src) (Vec3.make x y z) in
  let pts = List.init 40 (fun i -> let t = float_of_int i in (0.37 *. t, 0.11 *. t -. 2., 1.3 -. (0.07 *. t))) in
  List.iter
    (fun p ->
      let f1 = v "crackle form <1, 0, 0>" p and f1_l1 = v "crackle form <1, 0, 0> metric 1" p
      and f2_minus_f1 = v "crackle" p and same = v "crackle form <-1, 1, 0>" p in
      Scn.close ~eps:0. "the default form is <-1, 1, 0>" f2_minus_f1 same;
      if f1_l1 +. 1e-12 < f1 then Alcotest.failf "the L1 distance %g is below the L2 one %g" f1_l1 f1;
      (* POV-Ray adds the offset to the squared distance (metric 2) *)
      Scn.close ~eps:1e-12 "offset adds" (Float.min 1. (Float.sqrt ((f1 *. f1) +. 0.04)))
        (v "crackle form <1, 0, 0> offset 0.2" p))
    pts;
  (* the cubes' points are kept per domain in a few slots: a value is the
     same whatever was asked before (points in a few cubes and all over,
     many sharing a slot; asked again in the reverse order) *)
  let f = fn_pattern "crackle" in
  let st = Random.State.make [| 7 |] in
  let g a = Random.State.float st (2. *. a) -. a in
  let ps =
    Array.init 3000 (fun i ->
        match i mod 3 with
        | 0 -> Vec3.make (g 1.5) (g 1.5) (g 1.5)
        | 1 -> Vec3.make (g 60.) (g 60.) (g 60.)
        (* one column of cubes, far along one axis: cubes that differ in
           one coordinate by a multiple of the slots share a slot *)
        | _ -> Vec3.make (g 0.9) (g 0.9) (g 300.))
  in
  let first = Array.map (Pattern.value f) ps in
  for i = Array.length ps - 1 downto 0 do
    if Int64.bits_of_float (Pattern.value f ps.(i)) <> Int64.bits_of_float first.(i) then
      Alcotest.failf "crackle at %s: a different value asked again" (Vec3.to_string ps.(i))
  done;
  (* solid: one value around each feature point, whatever the point *)
  let a = v "crackle solid" (0.5, 0.5, 0.5) and b = v "crackle solid" (0.5001, 0.4999, 0.5) in
  Scn.close ~eps:0. "solid cells" a b;
  Scn.check_message "sphere { 0, 1 pigment { crackle metric 0 } }" "metric must be positive"

let function_values () =
  let pts = [ (0.5, 0.1); (1.2, 0.3); (-0.5, -0.5); (1., 0.); (1., 1.); (0., -2.3); (2., -0.1); (0., -1.) ] in
  let cases =
    [
      ("", [ 0.35; 0.74; 0.75; 1.; 0.; 0.70002; 0.9; 0. ]);
      ("frequency 2 phase 0.3", [ 1.; 0.77999001; 0.80000001; 0.29998001; 0.3; 0.70004001; 0.09998001; 0.30001001 ]);
      ("sine_wave", [ 0.9045085; 0.00098664; 0.; 0.5; 0.5; 0.02445233; 0.20610737; 0.5 ]);
      ("frequency 0", [ 0.35; 0.74; 0.75; 1.; 0.; 0.7; 0.9; 0. ]);
    ]
  in
  List.iter
    (fun (mods, expected) ->
      let p = fn_pattern ("function { x*x + y } " ^ mods) in
      List.iter2
        (fun (x, y) e ->
          Scn.close ~eps:1e-6 (Printf.sprintf "x*x + y %s at (%g, %g)" mods x y) e
            (Pattern.value p (Vec3.make x y 0.)))
        pts expected)
    cases

let function_declared () =
  let v src x y z =
    let s =
      Scn.compile
        (Printf.sprintf "#declare F = function { x + y*z } #declare G = function (a, b, c) { F(c, b, a) * 2 }
                         sphere { 0, 1 pigment { %s } }" src)
    in
    match s.objects.(0).texture with
    | { pigment = Pigment.Map { pattern; _ }; _ } :: _ -> Pattern.value pattern (Vec3.make x y z)
    | _ -> Alcotest.fail "no pattern"
  in
  Scn.close ~eps:1e-12 "F(x, y, z)" 0.5 (v "function { F(x, y, z) }" 0.1 0.2 2.);
  (* 2 (0.3 + 0.2 * 0.1) = 0.64 *)
  Scn.close ~eps:1e-12 "G(x, y, z), parameters a, b, c" 0.64 (v "function { G(x, y, z) }" 0.1 0.2 0.3);
  (* the pigment's transform takes the point into pattern space: x / 2,
     black to white *)
  let s = Scn.compile "sphere { 0, 1 pigment { function { x } scale 2 } }" in
  match s.objects.(0).texture with
  | { pigment; _ } :: _ -> Scn.close ~eps:1e-12 "scaled" 0.25 (Pigment.eval pigment (Vec3.make 0.5 0. 0.)).c.r
  | [] -> Alcotest.fail "no texture"

(* a pigment function's channels in a function pattern: gradient x from
   <0, 0.5, 1> to <1, 0.5, 0> at x = 0.25 is <0.25, 0.5, 0.75>, gray
   0.297 r + 0.589 g + 0.114 b (POV-Ray gives 4.7925 for .x + 10 .gray
   there) *)
let pigment_function () =
  let pf = "#declare PF = function { pigment { gradient x color_map { [0 rgbft <0, 0.5, 1, 0.2, 0.1>] [1 rgbft <1, 0.5, 0, 0.4, 0.3>] } } }\n" in
  let v member =
    let s = Scn.compile (pf ^ Printf.sprintf "sphere { 0, 1 pigment { function { PF(x, y, z).%s } } }" member) in
    match s.objects.(0).texture with
    | { pigment = Pigment.Map { pattern; _ }; _ } :: _ -> Pattern.value pattern (Vec3.make 0.25 0.3 0.7)
    | _ -> Alcotest.fail "no pattern"
  in
  List.iter
    (fun (m, e) -> Scn.close ~eps:1e-12 ("PF(x, y, z)." ^ m) e (v m))
    [ ("x", 0.25); ("red", 0.25); ("u", 0.25); ("y", 0.5); ("green", 0.5); ("v", 0.5); ("z", 0.75);
      ("blue", 0.75); ("t", 0.25); ("filter", 0.25); ("transmit", 0.15);
      ("gray", (0.297 *. 0.25) +. (0.589 *. 0.5) +. (0.114 *. 0.75)); ("grey", 0.45425) ]

(* evaluating a function pattern, a declared function, builtins, sum and
   select and a pigment function's channel included, allocates nothing *)
let function_allocation () =
  let s =
    Scn.compile
      "#declare F = function { x*x + y } \
       #declare PF = function { pigment { onion color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } } }\n\
       sphere { 0, 1 pigment { function { F(x, y, z) + sin(x) * 0.1 + select(y, 0.1, 0.2) + sum(i, 1, 3, i*z) * 0.01 \
       + max(x, y, 0) + PF(x, z, y).gray } } }"
  in
  let words = words_over_1000 ~y:0.2 ~z:(-0.3) (pattern_of s "the scene") in
  if words > 0. then Alcotest.failf "%.0f words for 1000 evaluations of a function pattern" words

(* the object pattern, against POV-Ray 3.7's function { pigment { object
   { ... } } } colours (read with #debug): first entry outside, second
   inside, blue and green by default; the surface itself is outside; the
   object moves with the pigment and takes its own transformations *)
let object_pattern () =
  let col src x y z =
    let s = Scn.compile (Printf.sprintf "#declare S = sphere { 0, 1 }\nplane { y, -9 pigment { %s } }" src) in
    let c = Pigment.eval (List.hd s.objects.(0).texture).pigment (Vec3.make x y z) in
    [ c.c.r; c.c.g; c.c.b ]
  in
  let check src (x, y, z) e =
    Alcotest.(check (list (float 1e-12))) (Printf.sprintf "%s at (%g, %g, %g)" src x y z) e (col src x y z)
  in
  let two = "object { S color rgb <1,0,0> color rgb <0,0,1> }" in
  check two (2., 0., 0.) [ 1.; 0.; 0. ];
  check two (0., 0., 0.) [ 0.; 0.; 1. ];
  check two (1., 0., 0.) [ 1.; 0.; 0. ];
  check "object { S }" (2., 0., 0.) [ 0.; 0.; 1. ];
  check "object { S }" (0., 0., 0.) [ 0.; 1.; 0. ];
  let scaled = "object { sphere { 0, 1 } pigment { rgb <0,1,0> }, pigment { rgb <0,0,1> } } scale 2" in
  check scaled (2.5, 0., 0.) [ 0.; 1.; 0. ];
  check scaled (1.5, 0., 0.) [ 0.; 0.; 1. ];
  let moved = "object { S scale 0.5 translate x color rgb 0 color rgb 1 }" in
  check moved (1., 0., 0.) [ 1.; 1.; 1. ];
  check moved (0., 0., 0.) [ 0.; 0.; 0. ];
  (* CSG: a ring of a sphere minus a slab *)
  let ring = "object { difference { sphere { 0, 1 } box { <-2,-0.2,-2>, <2,0.2,2> } } rgb 0, rgb 1 }" in
  check ring (0., 0.5, 0.) [ 1.; 1.; 1. ];
  check ring (0., 0.1, 0.) [ 0.; 0.; 0. ];
  (* textures and normals as the two cells *)
  let s =
    Scn.compile
      "sphere { 0, 1 texture { object { sphere { x, 0.5 } texture { pigment { rgb 1 } } texture { pigment { rgb 0.5 } } } } }"
  in
  (* (a normal written after a patterned texture is refused, as POV-Ray
     refuses it: the normal pattern goes on an object of its own) *)
  ignore (Scn.compile "sphere { 0, 1 normal { object { sphere { x, 0.5 } normal { bumps 0.5 } normal { dents 0.3 } } } }");
  (match s.objects.(0).texture with
  | { tmap = Some m; _ } :: _ ->
      Alcotest.(check int) "two textures" 2 (Array.length m.entries);
      Scn.close "inside" 1. (Pattern.value m.pattern (Vec3.make 0.9 0. 0.));
      Scn.close "outside" 0. (Pattern.value m.pattern (Vec3.make (-0.9) 0. 0.))
  | _ -> Alcotest.fail "no texture map");
  Scn.check_message "sphere { 0, 1 normal { object { sphere { 0, 1 } } } }" "needs its two normals";
  (* no allocation per evaluation *)
  let p =
    match (Scn.compile "sphere { 0, 1 pigment { object { union { sphere { 0, 1 } box { -2, -1 scale <1,2,1> } } rgb 0, rgb 1 } } }").objects.(0).texture with
    | { pigment = Pigment.Blocks { pattern; _ }; _ } :: _ -> pattern
    | _ -> Alcotest.fail "no block pigment"
  in
  let words = words_over_1000 ~prime:(0., 0., 0.) ~step:0.003 ~y:0.2 ~z:(-0.3) p in
  if words > 0. then Alcotest.failf "%.0f words for 1000 evaluations of an object pattern" words

(* cells, against POV-Ray 3.7's function { pattern { cells } } at the
   centres of cubes (x from -3 to 3, y from -2 to 2, z 0; then a few
   more), printed with #debug to six digits; an integer plane belongs to
   the cube above it (within 1e-10) *)
let cells () =
  let pov =
    [| [| 0.964889; 0.021556; 0.298064; 0.605938; 0.801348 |];
       [| 0.044166; 0.217732; 0.800280; 0.312386; 0.208935 |];
       [| 0.678652; 0.800879; 0.566955; 0.554328; 0.320046 |];
       [| 0.887014; 0.096533; 0.711819; 0.056343; 0.946322 |];
       [| 0.939083; 0.071445; 0.681271; 0.538597; 0.539091 |];
       [| 0.430278; 0.110809; 0.099090; 0.354116; 0.473289 |];
       [| 0.560107; 0.500211; 0.613932; 0.049533; 0.578923 |] |]
  in
  let p = fn_pattern "cells" in
  let v x y z = Pattern.value p (Vec3.make x y z) in
  Array.iteri
    (fun i row ->
      Array.iteri
        (fun j e ->
          let x = float_of_int (i - 3) +. 0.5 and y = float_of_int (j - 2) +. 0.5 in
          Scn.close ~eps:6e-7 (Printf.sprintf "cells at (%g, %g, 0.5)" x y) e (v x y 0.5))
        row)
    pov;
  List.iter
    (fun ((x, y, z), e) -> Scn.close ~eps:6e-7 (Printf.sprintf "cells at (%g, %g, %g)" x y z) e (v x y z))
    [ ((0.5, 0.5, 1.5), 0.992743); ((0.5, 0.5, -0.5), 0.824242); ((0.5, 0.5, 2.5), 0.429254);
      ((100.5, 0.5, 0.5), 0.154370); ((0.99999999999, 0.5, 0.5), 0.681271); ((0.9999999, 0.5, 0.5), 0.711819);
      ((-1e-13, 0.5, 0.5), 0.711819) ];
  (* the default colour map: black to white *)
  let s = Scn.compile "sphere { 0, 1 pigment { cells } }" in
  let c = Pigment.eval (List.hd s.objects.(0).texture).pigment (Vec3.make 0.5 0.5 0.5) in
  Scn.close ~eps:6e-7 "grey" 0.711819 c.c.g

let function_normal () =
  let s = Scn.compile "sphere { 0, 1 normal { function { abs(x) } 0.7 scale 0.5 } }" in
  match s.objects.(0).texture with
  | { normal = Some n; _ } :: _ ->
      Scn.close "bump size" 0.7 n.amount;
      Scn.close ~eps:1e-12 "value" 0.6 (Pattern.value n.pattern (Vec3.make (-0.6) 0. 0.))
  | _ -> Alcotest.fail "no normal"

(* density_file: POV-Ray 3.7's values for its spiral.df3 (50x50x5 voxels
   of one byte), read by #debug of pigment functions, without
   interpolation and trilinear; then the located errors *)
let density_file () =
  if not (Sys.file_exists "/usr/share/povray-3.7/include/spiral.df3") then print_endline "no spiral.df3: skipped"
  else begin
    let prelude i =
      Printf.sprintf
        "#declare P = function { pigment { density_file df3 \"spiral.df3\" interpolate %d color_map { [0 rgb 0] [1 rgb 1] } } }" i
    in
    List.iter
      (fun ((x, y, z), none, trilinear) ->
        let at i = Scn.float ~prelude:(prelude i) (Printf.sprintf "P(%g, %g, %g).red" x y z) in
        Scn.close ~eps:1e-7 "no interpolation" none (at 0);
        Scn.close ~eps:1e-7 "trilinear" trilinear (at 1))
      [ ((0.5, 0.5, 0.5), 1.0, 0.96666664); ((0.3, 0.61, 0.52), 0., 0.);
        ((0.5, 0.5, 0.995), 0.66274512, 0.66274512); ((0.45, 0.55, 0.505), 0.84705883, 0.80068630);
        (* outside the unit cube *)
        ((1.2, 0.5, 0.5), 0., 0.); ((0.5, -0.01, 0.5), 0., 0.) ];
    Scn.check_message "sphere { 0, 1 pigment { density_file df3 \"nowhere.df3\" } }" "cannot find density_file nowhere.df3";
    Scn.check_message "sphere { 0, 1 pigment { density_file df3 \"spiral.df3\" interpolate 3 } }"
      "interpolate is 0, 1 or 2, found 3"
  end

let function_errors () =
  Scn.check_message "sphere { 0, 1 pigment { function (a, b) { a + b } } }" "takes 3 parameters";
  Scn.check_message "#declare T = function { transform { scale 2 } }\nsphere { 0, 1 pigment { function { T(x, y, z) } } }"
    "take a component";
  Scn.check_message "#include \"functions.inc\"\nsphere { 0, 1 normal { function { f_mesh1(x, y, z, 1, 2, 3, 4, 5) } } }"
    "internal function"

let tests =
  ( "pattern",
    [
      Alcotest.test_case "exact patterns = POV-Ray" `Quick exact;
      Alcotest.test_case "hexagon and brick = POV-Ray" `Quick block_patterns;
      Alcotest.test_case "gradient and waves" `Quick gradient;
      Alcotest.test_case "maps" `Quick maps;
      Alcotest.test_case "transforms" `Quick transforms;
      Alcotest.test_case "maps' entries in the map's space = POV-Ray 3.7" `Quick map_space;
      Alcotest.test_case "normal bump size after a comma" `Quick normal_comma;
      Alcotest.test_case "image_map" `Quick image_map;
      Alcotest.test_case "image_map palette entries' filter and transmit" `Quick image_map_palette;
      Alcotest.test_case "image file types" `Quick image_kinds;
      Alcotest.test_case "hexagon on its cells' edges = POV-Ray's" `Quick hexagon_edges;
      Alcotest.test_case "brick on its mortar's edges = POV-Ray's" `Quick brick_edges;
      Alcotest.test_case "image_map interpolate 2, 3 and 4" `Quick image_map_interpolation;
      Alcotest.test_case "image_map map_type 5 (torus)" `Quick image_map_torus;
      Alcotest.test_case "image_map rows' edges as POV-Ray's map_pos" `Quick image_map_edges;
      Alcotest.test_case "spiral1 and spiral2" `Quick spirals;
      Alcotest.test_case "quilted" `Quick quilted;
      Alcotest.test_case "mandel" `Quick mandel;
      Alcotest.test_case "pattern modifier errors" `Quick pattern_errors;
      Alcotest.test_case "boxed, cylindrical, pigment_pattern; gradient, onion, radial wraps = POV-Ray" `Quick shape_patterns;
      Alcotest.test_case "slope_map heights" `Quick slope_map;
      Alcotest.test_case "warps: repeat, black_hole, order with transforms = POV-Ray" `Quick warps;
      Alcotest.test_case "mapping warps: planar, spherical, cylindrical, toroidal = POV-Ray" `Quick mapping_warps;
      Alcotest.test_case "julia = POV-Ray" `Quick julia;
      Alcotest.test_case "magnet = POV-Ray, allocation-free" `Quick magnet;
      Alcotest.test_case "slope = POV-Ray" `Quick slope;
      Alcotest.test_case "crackle form, metric, offset, solid" `Quick crackle_params;
      Alcotest.test_case "function patterns = POV-Ray" `Quick function_values;
      Alcotest.test_case "function patterns: declared functions" `Quick function_declared;
      Alcotest.test_case "function patterns: pigment function channels" `Quick pigment_function;
      Alcotest.test_case "function patterns allocate nothing" `Quick function_allocation;
      Alcotest.test_case "function normals" `Quick function_normal;
      Alcotest.test_case "object pattern = POV-Ray" `Quick object_pattern;
      Alcotest.test_case "cells = POV-Ray" `Quick cells;
      Alcotest.test_case "function pattern errors" `Quick function_errors;
      Alcotest.test_case "density_file: POV-Ray's values, errors" `Quick density_file;
    ]
    @ List.map QCheck_alcotest.to_alcotest fractal_props )
