(* bump_map and material_map (both read images through POV-Ray's planar
   mapping): POV-Ray's three-pixel rule worked by hand on small images,
   the scene language's forms and its errors. *)
open Camlray

(* 3 x 3 image, heights rising along the columns: 0, 0.25, 0.5 *)
let ramp ?(interpolate = 0) ?(once = false) () =
  Bump_map.make ~w:3 ~h:3 ~once ~interpolate ~by_index:false
    (Float.Array.init 9 (fun i -> 0.25 *. float_of_int (i mod 3)))

let tilt b amount (px, py) (nx, ny, nz) =
  let q = Vec3.m () and n = Vec3.m () and out = Vec3.m () in
  Vec3.set q px py 0.;
  Vec3.set n nx ny nz;
  Bump_map.tilt b amount q n out;
  [ out.mx; out.my; out.mz ]

let check msg e got = Alcotest.(check (list (float 1e-12))) msg e got

(* at the middle pixel: h1 = 0.25 there, h2 = 0 (left, a row down), h3 =
   0.5 (right, a row down); the triangle's normal (-(h3 - h2), 2,
   2 (h1 - h2) - (h3 - h2)) = (-0.5, 2, 0), unit, laid in the frame of
   the surface normal *)
let by_hand () =
  let l = Float.sqrt 4.25 in
  let bx = -0.5 /. l and by = 2. /. l in
  (* n = -z: x along (1, 0, 0), y along n, z = x cross y = (0, 1, 0) *)
  check "facing -z" [ bx; 0.; -.by ] (tilt (ramp ()) 1. (0.5, 0.5) (0., 0., -1.));
  (* n = +y: POV-Ray's frame for a normal along y: x, y, z themselves *)
  check "facing +y" [ bx; by; 0. ] (tilt (ramp ()) 1. (0.5, 0.5) (0., 1., 0.));
  (* the amount scales the heights *)
  let l2 = Float.sqrt 5. in
  check "amount 2" [ -1. /. l2; 0.; -2. /. l2 ] (tilt (ramp ()) 2. (0.5, 0.5) (0., 0., -1.));
  (* repeated: one unit over, the same *)
  check "repeats" (tilt (ramp ()) 1. (0.5, 0.5) (0., 0., -1.)) (tilt (ramp ()) 1. (1.5, -0.5) (0., 0., -1.));
  (* once: off the square the normal is left alone *)
  check "once, off the image" [ 0.; 0.; -1. ] (tilt (ramp ~once:true ()) 1. (1.5, 0.5) (0., 0., -1.));
  (* a flat image: the normal itself *)
  let flat = Bump_map.make ~w:2 ~h:2 ~once:false ~interpolate:2 ~by_index:false (Float.Array.make 4 0.7) in
  check "flat" [ 0.; 0.; -1. ] (tilt flat 3. (0.3, 0.6) (0., 0., -1.));
  (* no allocation per evaluation *)
  let b = ramp ~interpolate:2 () in
  let q = Vec3.m () and n = Vec3.m () and out = Vec3.m () in
  Vec3.set n 0. 0. (-1.);
  Bump_map.tilt b 1. q n out;
  let before = Gc.minor_words () in
  for i = 1 to 1000 do
    Vec3.set q (0.001 *. float_of_int i) 0.3 0.;
    Bump_map.tilt b 1. q n out
  done;
  let words = Gc.minor_words () -. before in
  if words > 0. then Alcotest.failf "%.0f words for 1000 bump map normals" words

(* the committed image, copied where scenes may read (the working folder) *)
let with_png f =
  let src = Filename.concat (Helpers.scenes_dir ()) "whitted-extra/bump-map.png" in
  let png = Printf.sprintf "bump-map-copy-%d.png" (Unix.getpid ()) in
  Helpers.write_file png (In_channel.with_open_bin src In_channel.input_all);
  Fun.protect ~finally:(fun () -> Sys.remove png) (fun () -> f png)

let parse () =
  with_png @@ fun png ->
  let s =
    Scn.compile
      (Printf.sprintf "plane { z, 0 normal { bump_map { png \"%s\" bump_size 3 interpolate 2 once use_color } scale 2 } }"
         png)
  in
  (match s.objects.(0).texture with
  | { normal = Some { map = Normal.Image _; amount; _ }; _ } :: _ -> Scn.close "bump_size" 3. amount
  | _ -> Alcotest.fail "no bump map");
  (* POV-Ray's default bump size, 0.5; bump_size after the block too *)
  let amount src =
    match (Scn.compile (Printf.sprintf "plane { z, 0 normal { bump_map { png \"%s\" } %s } }" png src)).objects.(0).texture with
    | { normal = Some { amount; _ }; _ } :: _ -> amount
    | _ -> Alcotest.fail "no normal"
  in
  Scn.close "default" 0.5 (amount "");
  Scn.close "after" 1.5 (amount "bump_size 1.5")

let errors () =
  with_png @@ fun png ->
  let m src = Printf.sprintf "plane { z, 0 normal { bump_map { png \"%s\" %s } } }" png src in
  Scn.check_message (m "map_type 1") "only 0 (planar)";
  Scn.check_message (m "interpolate 3") "interpolate 3 is not supported";
  Scn.check_message "plane { z, 0 normal { bump_map { png \"no-such-file.png\" } } }" "cannot find bump_map image no-such-file.png";
  (* a palette image read by index: the colour type is read first *)
  (* (written where the scene may read: the working folder) *)
  let f = Printf.sprintf "bump-map-palette-%d.png" (Unix.getpid ()) in
  Helpers.write_file f (Png_codec.signature ^ "\000\000\000\013IHDR\000\000\000\001\000\000\000\001\008\003\000\000\000");
  Scn.check_message (Printf.sprintf "plane { z, 0 normal { bump_map { png \"%s\" use_index } } }" f) "palette index";
  Sys.remove f



(* material_map, against POV-Ray 3.7's choices (measured on 8 x 1 images
   with three textures: palette indices 0..7 gave textures 0 1 2 2 1 2 0
   1, red bytes 0 1 2 3 4 128 254 255 gave 0 1 2 2 1 2 2 0: a number
   above the count is taken mod the count, the count itself is the last
   texture; colours not gamma-decoded) *)
let material_number src (x, y) =
  match (Scn.compile src).objects.(0).texture with
  | { tmap = Some m; _ } :: _ -> int_of_float (Pattern.value m.pattern (Vec3.make x y 0.))
  | _ -> Alcotest.fail "no material map"

let in_cwd name contents f =
  Helpers.write_file name contents;
  Fun.protect ~finally:(fun () -> Sys.remove name) (fun () -> f name)

let material_map () =
  let textures n = String.concat " " (List.init n (fun i -> Printf.sprintf "texture { pigment { rgb %d } }" i)) in
  let scene png extra n = Printf.sprintf "plane { z, 0 texture { material_map { png \"%s\" %s %s } } }" png extra (textures n) in
  let at i j = ((float_of_int i +. 0.5) /. 8., 1. -. ((float_of_int j +. 0.5) /. 1.)) in
  let reds = Bytes.of_string (String.concat "" (List.map (fun r -> Printf.sprintf "%c\200\050" (Char.chr r)) [ 0; 1; 2; 3; 4; 128; 254; 255 ])) in
  in_cwd (Printf.sprintf "mm-red-%d.png" (Unix.getpid ())) (Png_codec.encode 8 1 reds) (fun png ->
      List.iteri
        (fun i e -> Alcotest.(check int) (Printf.sprintf "red pixel %d" i) e (material_number (scene png "" 3) (at i 0)))
        [ 0; 1; 2; 2; 1; 2; 2; 0 ];
      (* once: off the image, the first texture *)
      Alcotest.(check int) "once, off" 0 (material_number (scene png "once" 3) (1.5, 0.5));
      Alcotest.(check int) "repeated" 2 (material_number (scene png "" 3) (1. +. fst (at 2 0), 0.5));
      Scn.check_message (scene png "map_type 2" 3) "only 0 (planar)";
      Scn.check_message (scene png "interpolate 2" 3) "interpolate in a material_map";
      Scn.check_message (scene png "" 0) "at least one texture");
  (* the committed palette image (16 x 16): index 0 at (1, 0), 1 at (5, 3),
     2 at (7, 6), 5 at (8, 6), 4 on the diagonals *)
  let src = Filename.concat (Helpers.scenes_dir ()) "whitted-extra/material-map.png" in
  in_cwd (Printf.sprintf "mm-pal-%d.png" (Unix.getpid ())) (In_channel.with_open_bin src In_channel.input_all) (fun png ->
      let px i j = ((float_of_int i +. 0.5) /. 16., 1. -. ((float_of_int j +. 0.5) /. 16.)) in
      List.iter
        (fun ((i, j), n, e) ->
          Alcotest.(check int) (Printf.sprintf "palette (%d, %d), %d textures" i j n) e (material_number (scene png "" n) (px i j)))
        [ ((1, 0), 4, 0); ((5, 3), 4, 1); ((7, 6), 4, 2); ((8, 6), 4, 1); ((0, 0), 4, 3); ((8, 6), 3, 2); ((0, 0), 3, 1) ])

let tests =
  ( "bump_map",
    [
      Alcotest.test_case "the three-pixel rule by hand, allocation-free" `Quick by_hand;
      Alcotest.test_case "parsed: bump_size, interpolate, once, use_color; default 0.5" `Quick parse;
      Alcotest.test_case "errors" `Quick errors;
      Alcotest.test_case "material_map = POV-Ray's choices" `Quick material_map;
    ] )
