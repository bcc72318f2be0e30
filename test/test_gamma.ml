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
  check "no #version + assumed_gamma 1" 218 "global_settings { assumed_gamma 1.0 }"

let tests = ("gamma", [ Alcotest.test_case "header rules" `Quick rules ])
