(* Shared helpers for tests that build scenes from scene-language text. *)
open Camlray
open Camlray_lang

let header = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"

let compile ?(raw = false) src =
  let src = if raw then src else header ^ src in
  match Parse.string src with
  | Error d -> Alcotest.failf "parse: %s" (Diag.to_string d)
  | Ok sdl -> (
      match Compile.scene sdl with
      | Error d -> Alcotest.failf "compile: %s" (Diag.to_string d)
      | Ok s -> s)

(* The linear colour of pixel (x, y) of a w x h render. *)
let pixel ?(w = 1) ?(h = 1) ?(x = 0) ?(y = 0) src =
  Whitted.pixel (compile src) ~width:w ~height:h x y

let close ?(eps = 5e-5) msg expected actual =
  if Float.abs (expected -. actual) > eps then
    Alcotest.failf "%s: expected %.5f, got %.5f" msg expected actual

let color ?eps msg (r, g, b) (c : Color.t) =
  close ?eps (msg ^ " (red)") r c.r;
  close ?eps (msg ^ " (green)") g c.g;
  close ?eps (msg ^ " (blue)") b c.b

let gray ?eps msg v c = color ?eps msg (v, v, v) c
