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

let tests = ("gamma", [ Alcotest.test_case "header rules" `Quick rules ])
