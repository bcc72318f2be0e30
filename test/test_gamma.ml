(* Gamma rules (pov-facts.md 4): a head-on lit white plane (linear 0.7)
   written to an 8-bit file under each scene header. *)
open Camlray

let file_value header =
  let s =
    Scn.compile ~raw:true
      (header ^ "\nlight_source { <0,0,-10>, rgb 1 }\nplane { z, 1 pigment { rgb 1 } }")
  in
  let img = Image.create 1 1 in
  let c = Whitted.pixel s ~width:1 ~height:1 0 0 in
  Image.set img 0 0 c.r c.g c.b;
  Char.code (Bytes.get (Image.to_rgb8 s.settings.encoding img).data 0)

let rules () =
  let check msg expected header = Alcotest.(check int) msg expected (file_value header) in
  check "3.7 + assumed_gamma 1" 218 "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }";
  check "3.7 without assumed_gamma" 218 "#version 3.7;";
  check "no #version" 179 "";
  check "no #version + assumed_gamma 1" 218 "global_settings { assumed_gamma 1.0 }";
  (* assumed_gamma g <> 1, whatever the version: sRGB of x^g (povray 3.7
     writes 0.7 as 0.705776 for g = 2.2 and 0.752377 for g = 1.8) *)
  check "3.7 + assumed_gamma 2.2" 180 "#version 3.7;\nglobal_settings { assumed_gamma 2.2 }";
  check "3.6 + assumed_gamma 2.2" 180 "#version 3.6;\nglobal_settings { assumed_gamma 2.2 }";
  check "no #version + assumed_gamma 2.2" 180 "global_settings { assumed_gamma 2.2 }";
  check "3.7 + assumed_gamma 1.8" 192 "#version 3.7;\nglobal_settings { assumed_gamma 1.8 }"

(* POV-Ray 3.7 carries sRGB colours, and the colours of image files,
   into the working gamma (assumed_gamma): under assumed_gamma 2.2 an
   srgb <0.5, 0.25, 0.75> at ambient 1 is written 128, 64, 191 (POV-Ray's
   file), and an image's colours come out as they are in the file
   (advanced/sunsethf went from 23.9 dB to identical) *)
let working_gamma () =
  let bytes header body =
    let s = Scn.compile ~raw:true (header ^ "\ncamera { orthographic location <0.5, 0.5, -1> look_at <0.5, 0.5, 0> right x up y }\n" ^ body) in
    let img = Image.create 1 1 in
    let c = Whitted.pixel s ~width:1 ~height:1 0 0 in
    Image.set img 0 0 c.r c.g c.b;
    let d = (Image.to_rgb8 s.settings.encoding img).data in
    List.init 3 (fun k -> Char.code (Bytes.get d k))
  in
  let plane p = Printf.sprintf "plane { z, 0 pigment { %s } finish { ambient 1 diffuse 0 } }" p in
  let h g = Printf.sprintf "#version 3.7;\nglobal_settings { assumed_gamma %g }" g in
  Alcotest.(check (list int)) "srgb under assumed_gamma 2.2" [ 128; 64; 191 ] (bytes (h 2.2) (plane "srgb <0.5, 0.25, 0.75>"));
  Alcotest.(check (list int)) "srgb under assumed_gamma 1" [ 128; 64; 191 ] (bytes (h 1.) (plane "srgb <0.5, 0.25, 0.75>"));
  (* an opaque image: the same bytes under any working gamma *)
  (* beside the tests (scenes read only there), removed after *)
  let png = Printf.sprintf "gamma-%d.png" (Unix.getpid ()) in
  Fun.protect ~finally:(fun () -> if Sys.file_exists png then Sys.remove png) @@ fun () ->
  let im = Image.create 1 1 in
  (* a linear 0.2, 0.5, 0.8 written as sRGB bytes *)
  Image.set im 0 0 0.2 0.5 0.8;
  Image.write_png png (Image.to_rgb8 Image.Srgb im);
  let image g = bytes (h g) (plane (Printf.sprintf "image_map { png \"%s\" }" png)) in
  let file = List.init 3 (fun k -> Char.code (Bytes.get (Image.to_rgb8 Image.Srgb im).data k)) in
  Alcotest.(check (list int)) "an image under assumed_gamma 1: the file's bytes" file (image 1.);
  Alcotest.(check (list int)) "under assumed_gamma 2.2: the file's bytes" file (image 2.2)

(* an image_map's alpha is its transmit (1 - alpha), as in POV-Ray:
   the harness's 16 x 16 RGBA PNG on a plane at ambient 1 before a black
   background, 8 x 6 pixels, against POV-Ray's file at four pixels (it
   was drawn opaque: 14.1 dB) *)
let image_alpha () =
  let png = Printf.sprintf "alpha-%d.png" (Unix.getpid ()) in
  Helpers.write_file png
    (In_channel.with_open_bin (Filename.concat (Helpers.scenes_dir ()) "whitted-extra/image-pattern.png") In_channel.input_all);
  Fun.protect ~finally:(fun () -> Sys.remove png) @@ fun () ->
  let s =
    Scn.compile ~raw:true
      (Printf.sprintf
         "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n\
          camera { orthographic location <0.5, 0.5, -1> look_at <0.5, 0.5, 0> right x up y }\n\
          plane { z, 0 pigment { image_map { png \"%s\" } } finish { ambient 1 diffuse 0 } }"
         png)
  in
  let img = Render.image ~domains:1 ~width:8 ~height:6 (Whitted.pixel s ~width:8 ~height:6) in
  let d = (Image.to_rgb8 s.settings.encoding img).data in
  let at x y = List.init 3 (fun k -> Char.code (Bytes.get d ((3 * ((8 * y) + x)) + k))) in
  List.iter
    (fun (x, y, want) -> Alcotest.(check (list int)) (Printf.sprintf "pixel %d, %d" x y) want (at x y))
    [ (0, 0, [ 4; 4; 195 ]); (0, 3, [ 35; 67; 0 ]); (0, 5, [ 1; 3; 124 ]); (3, 2, [ 88; 83; 100 ]) ]

let tests =
  ( "gamma",
    [ Alcotest.test_case "header rules" `Quick rules;
      Alcotest.test_case "srgb and image colours in the working gamma" `Quick working_gamma;
      Alcotest.test_case "an image_map's alpha is its transmit" `Quick image_alpha ] )
