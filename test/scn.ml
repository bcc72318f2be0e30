(* Helpers for tests that read scene text: parse a string, pull values
   back out through sphere radii and centres. *)
open Camlray_lang

let parse ?(name = "<test>") text =
  match Parse.string ~name text with
  | Ok s -> s
  | Error d -> Alcotest.failf "unexpected error:\n%s" (Diag.to_string d)

let error ?(name = "<test>") text =
  match Parse.string ~name text with
  | Ok _ -> Alcotest.failf "expected an error for:\n%s" text
  | Error d -> d

let spheres (s : Sdl.scene) =
  List.filter_map
    (function
      | Sdl.Object { Sdl.shape = Sdl.Sphere (c, r); _ } -> Some (c, r) | _ -> None)
    s.items

(* The value of a float expression, evaluated after [prelude]. *)
let float ?(prelude = "") e =
  match spheres (parse (Printf.sprintf "%s\nsphere { 0, %s }\n" prelude e)) with
  | [ (_, r) ] -> r
  | l -> Alcotest.failf "expected one sphere, got %d" (List.length l)

(* All the floats a scene produces, one sphere radius each, in order. *)
let floats text = List.map snd (spheres (parse text))

let vec ?(prelude = "") e =
  match spheres (parse (Printf.sprintf "%s\nsphere { %s, 1 }\n" prelude e)) with
  | [ ((c : Camlray.Vec3.t), _) ] -> [ c.x; c.y; c.z ]
  | l -> Alcotest.failf "expected one sphere, got %d" (List.length l)

let check_float ?(eps = 1e-9) msg expected got =
  Alcotest.(check (float eps)) msg expected got

let check_floats ?(eps = 1e-9) msg expected got =
  Alcotest.(check (list (float eps))) msg expected got

(* The message of the error a text gives (without location). *)
let message text = (error text).Diag.msg

let contains s sub =
  let n = String.length sub and m = String.length s in
  let rec go i = i + n <= m && (String.sub s i n = sub || go (i + 1)) in
  go 0

let check_message text sub =
  let m = message text in
  if not (contains m sub) then Alcotest.failf "message %S does not contain %S" m sub

(* Whole scenes: compile and shade (the Whitted tests). *)
open Camlray

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
let pixel ?(raw = false) ?(w = 1) ?(h = 1) ?(x = 0) ?(y = 0) src =
  Whitted.pixel (compile ~raw src) ~width:w ~height:h x y

let close ?(eps = 5e-5) msg expected actual =
  if Float.abs (expected -. actual) > eps then
    Alcotest.failf "%s: expected %.5f, got %.5f" msg expected actual

let color ?eps msg (r, g, b) (c : Color.t) =
  close ?eps (msg ^ " (red)") r c.r;
  close ?eps (msg ^ " (green)") g c.g;
  close ?eps (msg ^ " (blue)") b c.b

let gray ?eps msg v c = color ?eps msg (v, v, v) c
