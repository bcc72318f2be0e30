(* bump_map, material_map and image_pattern (all read images through
   POV-Ray's mappings): POV-Ray's three-pixel rule worked by hand on
   small images, image_pattern's values against POV-Ray's, the scene
   language's forms and its errors. *)
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
  Scn.check_message (Printf.sprintf "plane { z, 0 normal { bump_map { png \"%s\" use_index interpolate 2 } } }" f)
    "interpolated bump_map by palette index";
  (* read by index, not interpolated: the damaged file is told *)
  Scn.check_message (Printf.sprintf "plane { z, 0 normal { bump_map { png \"%s\" use_index } } }" f) "cannot read bump_map";
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

(* {1 image_pattern} *)

(* A PNG of any colour type and depth, for the kinds camlray's encoder
   does not write (grey, palettes with transparency): the rows
   unfiltered, in one stored deflate block *)
let crc_table =
  Array.init 256 (fun n ->
      let c = ref n in
      for _ = 0 to 7 do
        c := if !c land 1 = 1 then 0xEDB88320 lxor (!c lsr 1) else !c lsr 1
      done;
      !c)

let crc s =
  let c = ref 0xFFFFFFFF in
  String.iter (fun ch -> c := crc_table.((!c lxor Char.code ch) land 0xFF) lxor (!c lsr 8)) s;
  !c lxor 0xFFFFFFFF

let be32 n = String.init 4 (fun i -> Char.chr ((n lsr (8 * (3 - i))) land 0xFF))
let chunk typ data = be32 (String.length data) ^ typ ^ data ^ be32 (crc (typ ^ data))

let png ~depth ~colour_type ?(plte = "") ?(trns = "") w h rows =
  let raw = String.concat "" (List.map (fun r -> "\000" ^ r) rows) in
  let n = String.length raw in
  let le16 v = String.init 2 (fun i -> Char.chr ((v lsr (8 * i)) land 0xFF)) in
  let z = "\x78\x01\x01" ^ le16 n ^ le16 (lnot n) ^ raw ^ be32 (Png_codec.adler32 raw 0 n) in
  let opt typ d = if d = "" then "" else chunk typ d in
  Png_codec.signature
  ^ chunk "IHDR" (be32 w ^ be32 h ^ String.make 1 (Char.chr depth) ^ String.make 1 (Char.chr colour_type) ^ "\000\000\000")
  ^ opt "PLTE" plte ^ opt "tRNS" trns ^ chunk "IDAT" z ^ chunk "IEND" ""

(* the image pattern of a scene's first object's pigment, its values at
   points (pattern space is world space here) *)
let image_values png mods points =
  let src = Printf.sprintf "plane { z, 0 pigment { image_pattern { png \"%s\" %s } } }" png mods in
  match (Scn.compile src).objects.(0).texture with
  | { pigment = Pigment.Map { pattern = { kind = Pattern.Image _; _ } as p; _ }; _ } :: _ ->
      List.map (fun (x, y, z) -> Pattern.value p (Vec3.make x y z)) points
  | _ -> Alcotest.fail "no image pattern"

let committed name = In_channel.with_open_bin (Filename.concat (Helpers.scenes_dir ()) name) In_channel.input_all

(* The harness scene's 16 x 16 RGBA PNG, through every form, against
   POV-Ray 3.7's values at the same points (printed by #debug through
   function { pigment { image_pattern { ... } color_map { [0 rgb 0] [1
   rgb 1] } } }; POV-Ray's colours are single precision, hence 1e-7) *)
let pov_values () =
  in_cwd (Printf.sprintf "ip-%d.png" (Unix.getpid ())) (committed "whitted-extra/image-pattern.png") @@ fun png ->
  List.iter
    (fun (mods, cases) ->
      let got = image_values png mods (List.map fst cases) in
      List.iter2
        (fun ((x, y, z), e) v -> Scn.close ~eps:1e-7 (Printf.sprintf "image_pattern { %s } at (%g, %g, %g)" mods x y z) e v)
        cases got)
    [
      ( "",
        [ ((0.03125, 0.96875, 0.), 0.147074521); ((0.5, 0.5, 0.), 0.552364707); ((0.7, 0.2, 0.3), 0.687752962);
          ((1.3, -0.4, 0.), 0.129466668); ((-0.35, 2.1, 5.), 0.747686267) ] );
      ("", [ ((0.28125, 0.96875, 0.), 0.203698054); ((0.3, 0.3, 0.), 0.415031374) ]);
      ( "interpolate 2",
        [ ((0.5, 0.5, 0.), 0.557517648); ((0.27, 0.61, 0.), 0.178552821); ((0.01, 0.99, 0.), 0.188421175);
          ((1.6, -0.8, 0.), 0.495941281) ] );
      (* once: 0 off the image; x = 1 reads the first column (POV-Ray) *)
      ( "interpolate 4 once",
        [ ((0.27, 0.61, 0.), 0.168933600); ((0.99, 0.02, 0.), 0.268682361); ((1.2, 0.5, 0.), 0.);
          ((0.5, -0.1, 0.), 0.); ((1.0, 0.5, 0.), 0.409896076) ] );
      (* 1 - alpha *)
      ( "use_alpha",
        [ ((0.28125, 0.96875, 0.), 0.627450943); ((0.15625, 0.78125, 0.), 0.984313726); ((0.5, 0.5, 0.), 0.);
          ((0.3, 0.3, 0.), 0.533333302) ] );
      ("use_alpha interpolate 2", [ ((0.31, 0.47, 0.), 0.143607840) ]);
      (* the pole, and the centre (no place on the image: 0) *)
      ( "map_type 1",
        [ ((0.6, 0.48, -0.64), 0.608921587); ((-1., 0.2, 0.3), 0.541882396); ((0., 1., 0.), 0.227917656);
          ((0., 0., 0.), 0.) ] );
      ("map_type 2", [ ((0.8, 0.3, 0.6), 0.509764731); ((-0.5, -0.7, -0.5), 0.258854896) ]);
      ("map_type 2 once", [ ((0.3, 1.2, 0.1), 0.); ((0.3, 0.2, 0.1), 0.180098042) ]);
      (* the axis: 0 *)
      ( "map_type 5 interpolate 2",
        [ ((1.2, 0.1, 0.3), 0.396974683); ((-0.9, -0.2, 0.5), 0.163019210); ((0., 0.5, 0.), 0.) ] );
      (* the file's values decoded as c^2.2 before the grey *)
      ("gamma 2.2", [ ((0.5, 0.5, 0.), 0.301491499); ((0.27, 0.61, 0.), 0.058294110) ]);
    ];
  (* frequency 0 (POV-Ray's parser sets it): phase is ignored; frequency
     2 wraps (POV-Ray: 0.407396108, 0.104719415) *)
  let at mods p =
    match (Scn.compile (Printf.sprintf "plane { z, 0 pigment { image_pattern { png \"%s\" } %s } }" png mods)).objects.(0).texture with
    | { pigment = Pigment.Map { pattern; xform; _ }; _ } :: _ ->
        let q = Vec3.m () and w = Pattern.work () in
        let x, y, z = p in
        Vec3.set q x y z;
        Pattern.eval_at pattern xform q w
    | _ -> Alcotest.fail "no pattern"
  in
  Scn.close ~eps:1e-7 "phase 0.3" 0.203698054 (at "phase 0.3" (0.28125, 0.96875, 0.));
  Scn.close ~eps:1e-7 "frequency 2" 0.407396108 (at "frequency 2" (0.28125, 0.96875, 0.));
  Scn.close ~eps:1e-7 "frequency 2" 0.104719415 (at "frequency 2" (0.5, 0.5, 0.))

(* The rule on images made here: the grey of the file's bytes, the red
   without alpha, palettes, and POV-Ray's storage of grey PNGs *)
let by_rule () =
  let centre w h i j = ((float_of_int i +. 0.5) /. float_of_int w, 1. -. ((float_of_int j +. 0.5) /. float_of_int h), 0.) in
  (* 3 x 2 RGB: the grey 0.297 r + 0.589 g + 0.114 b of each pixel, not
     gamma-decoded; use_alpha without alpha: the red *)
  let px = [| (255, 0, 0); (0, 255, 0); (0, 0, 255); (10, 200, 90); (255, 255, 255); (0, 0, 0) |] in
  let data = Bytes.create 18 in
  Array.iteri (fun k (r, g, b) -> Bytes.set data (3 * k) (Char.chr r); Bytes.set data ((3 * k) + 1) (Char.chr g); Bytes.set data ((3 * k) + 2) (Char.chr b)) px;
  in_cwd (Printf.sprintf "ip-rgb-%d.png" (Unix.getpid ())) (Png_codec.encode 3 2 data) (fun f ->
      let points = List.init 6 (fun k -> centre 3 2 (k mod 3) (k / 3)) in
      let grey = image_values f "" points and red = image_values f "use_alpha" points in
      Array.iteri
        (fun k (r, g, b) ->
          let c v = float_of_int v /. 255. in
          Scn.close ~eps:1e-12 (Printf.sprintf "grey of pixel %d" k) (Bump_map.grey (c r) (c g) (c b)) (List.nth grey k);
          Scn.close ~eps:1e-12 (Printf.sprintf "red of pixel %d" k) (c r) (List.nth red k))
        px;
      (* white stays 1 (frequency 0: not wrapped) *)
      Scn.close ~eps:1e-12 "white" 1. (List.nth grey 4);
      (* repeated without once, 0 beyond the image with it *)
      Alcotest.(check (list (float 1e-12))) "repeated" [ List.nth grey 3 ] (image_values f "" [ (2. +. (1. /. 6.), -1.75, 3.) ]);
      Alcotest.(check (list (float 0.))) "once" [ 0.; 0.; 0.; 0. ]
        (image_values f "once" [ (1.01, 0.5, 0.); (-0.01, 0.5, 0.); (0.5, 1.01, 0.); (0.5, -0.01, 0.) ]));
  (* an 8-bit grey PNG of every level: POV-Ray keeps it as the single
     precision grey of each level truncated to a byte, 84 levels one
     lower (measured: these) *)
  let lower =
    [ 3; 5; 6; 10; 12; 20; 23; 24; 25; 29; 31; 35; 40; 43; 45; 46; 48; 50; 51; 53; 55; 58; 61; 62; 70; 75; 80; 85;
      86; 90; 92; 95; 96; 100; 102; 105; 106; 109; 110; 111; 116; 117; 121; 122; 124; 127; 140; 145; 150; 157;
      160; 170; 172; 177; 180; 184; 187; 190; 192; 197; 199; 200; 204; 207; 210; 211; 212; 217; 218; 220; 221;
      222; 227; 231; 232; 234; 235; 237; 241; 242; 244; 247; 248; 254 ]
  in
  let rows = List.init 16 (fun j -> String.init 16 (fun i -> Char.chr ((16 * j) + i))) in
  in_cwd (Printf.sprintf "ip-grey-%d.png" (Unix.getpid ())) (png ~depth:8 ~colour_type:0 16 16 rows) (fun f ->
      let got = image_values f "" (List.init 256 (fun k -> centre 16 16 (k mod 16) (k / 16))) in
      let read = List.map (fun v -> Float.round (v *. 255.)) got in
      List.iteri (fun k v -> Scn.close ~eps:1e-12 (Printf.sprintf "level %d exactly a level" k) (v /. 255.) (List.nth got k)) read;
      List.iteri
        (fun k v ->
          let e = if List.mem k lower then k - 1 else k in
          Scn.close ~eps:0. (Printf.sprintf "level %d" k) (float_of_int e) v)
        read);
  (* a palette: its colours' grey (use_index alike); use_alpha: 1 - the
     tRNS alpha (255 past it), 0 everywhere without tRNS (POV-Ray) *)
  let plte = "\255\000\000" ^ "\000\255\000" ^ "\000\000\255" ^ "\128\128\128" in
  let rows = [ "\000\001\002\003" ] in
  let points = List.init 4 (fun i -> centre 4 1 i 0) in
  let c v = float_of_int v /. 255. in
  let greys = [ Bump_map.grey 1. 0. 0.; Bump_map.grey 0. 1. 0.; Bump_map.grey 0. 0. 1.; c 128 ] in
  in_cwd (Printf.sprintf "ip-pal-%d.png" (Unix.getpid ())) (png ~depth:8 ~colour_type:3 ~plte ~trns:"\000\100" 4 1 rows) (fun f ->
      Alcotest.(check (list (float 1e-12))) "palette greys" greys (image_values f "" points);
      Alcotest.(check (list (float 1e-12))) "use_index" greys (image_values f "use_index" points);
      Alcotest.(check (list (float 1e-12))) "tRNS" [ 1.; 1. -. c 100; 0.; 0. ] (image_values f "use_alpha" points));
  in_cwd (Printf.sprintf "ip-pal2-%d.png" (Unix.getpid ())) (png ~depth:8 ~colour_type:3 ~plte 4 1 rows) (fun f ->
      Alcotest.(check (list (float 0.))) "no tRNS" [ 0.; 0.; 0.; 0. ] (image_values f "use_alpha" points))

(* evaluated with nothing allocated, every mapping *)
let image_allocation () =
  in_cwd (Printf.sprintf "ip-alloc-%d.png" (Unix.getpid ())) (committed "whitted-extra/image-pattern.png") @@ fun png ->
  List.iter
    (fun mods ->
      let src = Printf.sprintf "plane { z, 0 pigment { image_pattern { png \"%s\" %s } } }" png mods in
      match (Scn.compile src).objects.(0).texture with
      | { pigment = Pigment.Map { pattern; _ }; _ } :: _ ->
          let q = Vec3.m () and w = Pattern.work () in
          Pattern.eval_m pattern q w;
          let before = Gc.minor_words () in
          for i = 1 to 1000 do
            Vec3.set q (0.013 *. float_of_int i) (0.3 -. (0.007 *. float_of_int i)) 0.4;
            Pattern.eval_m pattern q w
          done;
          let words = Gc.minor_words () -. before in
          if words > 0. then Alcotest.failf "image_pattern { %s }: %.0f words for 1000 evaluations" mods words
      | _ -> Alcotest.fail "no image pattern")
    [ ""; "interpolate 2 once"; "interpolate 4 map_type 1"; "map_type 2"; "map_type 5 use_alpha" ]

(* A normal's +y sample 0.02 above y = 0.48 falls on the row edge at 0.5
   of a 1 x 2 image (white above black): POV-Ray's accuracy, a float
   (0.0199999995...), keeps it in the black row, so the normal is not
   tilted; 6e-10 higher it reads the white row (POV-Ray, measured on 1 x
   1 renders: 0.70880 at y = 0.48, the flat plane's shade, 0 at
   0.4800000006) *)
let row_edge () =
  let data = Bytes.of_string "\255\255\255\000\000\000" in
  in_cwd (Printf.sprintf "ip-edge-%d.png" (Unix.getpid ())) (Png_codec.encode 1 2 data) @@ fun png ->
  match (Scn.compile (Printf.sprintf "plane { z, 0 normal { image_pattern { png \"%s\" } 2 } }" png)).objects.(0).texture with
  | { normal = Some nm; _ } :: _ ->
      let tilt y =
        let p = Vec3.m () and n = Vec3.m () and out = Vec3.m () in
        Vec3.set p 0.3 y 0.;
        Vec3.set n 0. 0. (-1.);
        Normal.perturb_m nm p n out;
        [ out.mx; out.my; out.mz ]
      in
      Alcotest.(check (list (float 1e-12))) "y = 0.48: flat" [ 0.; 0.; -1. ] (tilt 0.48);
      if Float.abs (List.nth (tilt 0.4800000006) 1) < 0.1 then Alcotest.fail "y = 0.4800000006: not tilted"
  | _ -> Alcotest.fail "no normal"

let image_errors () =
  in_cwd (Printf.sprintf "ip-err-%d.png" (Unix.getpid ())) (committed "whitted-extra/image-pattern.png") @@ fun png ->
  let m src = Printf.sprintf "plane { z, 0 pigment { image_pattern { png \"%s\" %s } } }" png src in
  Scn.check_message (m "interpolate 3") "an image_pattern's interpolate 3 is not supported";
  Scn.check_message (m "bump_size 2") "bump_size";
  Scn.check_message "plane { z, 0 pigment { image_pattern { png \"no-such-file.png\" } } }"
    "cannot find image_pattern image no-such-file.png";
  (* in a normal and a texture_map, as any pattern *)
  (match (Scn.compile (Printf.sprintf "plane { z, 0 normal { image_pattern { png \"%s\" } 0.7 } }" png)).objects.(0).texture with
  | { normal = Some { pattern = { kind = Pattern.Image _; _ }; amount; _ }; _ } :: _ -> Scn.close "bump size" 0.7 amount
  | _ -> Alcotest.fail "no image_pattern normal");
  match
    (Scn.compile
       (Printf.sprintf "plane { z, 0 texture { image_pattern { png \"%s\" } texture_map { [0 pigment { rgb 0 }] [1 pigment { rgb 1 }] } } }" png))
      .objects.(0).texture
  with
  | { tmap = Some { pattern = { kind = Pattern.Image _; _ }; _ }; _ } :: _ -> ()
  | _ -> Alcotest.fail "no image_pattern texture_map"

let tests =
  ( "bump_map",
    [
      Alcotest.test_case "the three-pixel rule by hand, allocation-free" `Quick by_hand;
      Alcotest.test_case "parsed: bump_size, interpolate, once, use_color; default 0.5" `Quick parse;
      Alcotest.test_case "errors" `Quick errors;
      Alcotest.test_case "material_map = POV-Ray's choices" `Quick material_map;
      Alcotest.test_case "image_pattern = POV-Ray's values, every form and mapping" `Quick pov_values;
      Alcotest.test_case "image_pattern's rule on images made here (RGB, grey, palette)" `Quick by_rule;
      Alcotest.test_case "image_pattern allocates nothing" `Quick image_allocation;
      Alcotest.test_case "image_pattern in normals and texture maps; errors" `Quick image_errors;
      Alcotest.test_case "image_pattern normals: a sample on a row's edge reads POV-Ray's row" `Quick row_edge;
    ] )
