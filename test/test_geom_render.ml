(* Cross-render: each shape and CSG operator rendered by camlray and by
   POV-Ray 3.7 at 160x120 without anti-aliasing must agree apart from
   edges: at least 99% of pixels with every channel within 2/255, and PSNR
   at least 35 dB. Skipped when povray is not installed. *)
open Camlray

let scenes = [
    (* glass inside a hollow sphere around the camera: POV-Ray weighs the
       fresnel reflection of a ray leaving the glass by the index ratio
       of the innermost interior (the glass) over the glass's, 1, so no
       light is reflected back in from its faces *)
    ("glass-in-a-hollow-sky", {pov|#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <-5, 10, -6> color rgb 1 }
sphere { 0, 50 hollow
  pigment { gradient y color_map { [0 rgb <0.2, 0.3, 0.6>] [1 rgb <0.9, 0.8, 0.6>] } scale 100 translate -50*y }
  finish { ambient 1 diffuse 0 } }
plane { y, -0.5 pigment { checker rgb 0.9 rgb <0.6, 0.1, 0.1> } }
box { <-1, -0.5, -1>, <1, 1.5, 1> rotate y*30
  pigment { rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel } }
  interior { ior 1.5 } }
|pov});
    ("open", {pov|#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -5> look_at <0, 0, 0> }
light_source { <-5, 10, -6> color rgb 1 }
background { color rgb <0.3, 0.4, 0.6> }
cylinder { <-1.2, -1, 0>, <-1.2, 1, 0>, 0.8 open pigment { rgb <0.9,0.5,0.2> } }
cone { <1.2, -1, 0>, 0.3, <1.2, 1, 0>, 0.9 open pigment { rgb <0.2,0.5,0.9> } }
disc { <0,-1,0>, y, 3 pigment { rgb 0.8 } }
|pov});
    ("shapes", {pov|#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.5, 0> right x*4/3 }
light_source { <-5, 10, -6> color rgb 1 }
background { color rgb <0.3, 0.4, 0.6> }
plane { y, -0.5 pigment { rgb <0.7, 0.7, 0.6> } }
box { <-4, -0.5, 1>, <-2.5, 1, 2.5> pigment { rgb <0.9, 0.2, 0.2> } }
cylinder { <-1.5, -0.5, 1.5>, <-1.5, 1.5, 1.5>, 0.6 pigment { rgb <0.2, 0.9, 0.2> } }
cone { <0.5, -0.5, 1.5>, 0.8, <0.5, 1.5, 1.5>, 0.2 pigment { rgb <0.2, 0.2, 0.9> } }
torus { 1, 0.3 rotate x*60 translate <2.8, 0.8, 1.5> pigment { rgb <0.9, 0.9, 0.2> } }
disc { <-3, 0.2, -2>, <0, 1, -1>, 0.8, 0.3 pigment { rgb <0.9, 0.2, 0.9> } }
triangle { <-1.5, -0.5, -2>, <-0.5, 1.2, -1.5>, <0.3, -0.5, -2.5> pigment { rgb <0.2, 0.9, 0.9> } }
smooth_triangle { <0.8, -0.5, -2>, <-1,0,-1>, <1.8, 1.2, -1.5>, <0,1,-1>, <2.6, -0.5, -2.5>, <1,0,-1> pigment { rgb <1, 0.6, 0.2> } }
cylinder { <3.5, -0.3, -2>, <4.5, 0.8, -1.5>, 0.4 open pigment { rgb <0.6, 0.6, 1> } }
|pov});
    ("csg", {pov|#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.5, 0> right x*4/3 }
light_source { <-5, 10, -6> color rgb 1 }
background { color rgb <0.3, 0.4, 0.6> }
plane { y, -0.5 pigment { rgb <0.7, 0.7, 0.6> } }
difference {
  box { -1, 1 pigment { rgb <0.9, 0.2, 0.2> } }
  sphere { 0, 1.3 pigment { rgb <0.2, 0.9, 0.2> } }
  cylinder { -2*x, 2*x, 0.5 }
  pigment { rgb <0.9, 0.9, 0.2> }
  rotate y*30 translate <-3, 0.5, 1>
}
intersection {
  sphere { 0, 1 }
  box { <-2, -0.3, -2>, <2, 2, 2> pigment { rgb <0.2, 0.3, 0.9> } }
  pigment { rgb <0.9, 0.5, 0.1> }
  translate <0, 0.5, 1>
}
merge {
  sphere { <-0.4, 0, 0>, 0.7 }
  sphere { <0.4, 0, 0>, 0.7 }
  pigment { rgb <0.2, 0.8, 0.8> }
  translate <3, 0.4, 1>
}
union {
  torus { 0.6, 0.15 }
  cylinder { -0.5*y, 0.5*y, 0.2 pigment { rgb 1 } }
  pigment { rgb <0.8, 0.2, 0.8> }
  rotate x*-30 translate <-2, 0.3, -2.5>
}
sphere { 0, 0.8 clipped_by { plane { y, 0.2 } } pigment { rgb <1, 0.6, 0.2> } translate <0.5, 0.3, -2.5> }
object { sphere { 0, 100 inverse } pigment { rgb 0.5 } }
intersection { sphere { 0, 0.7 } plane { x, 0.2 inverse } pigment { rgb <0.5, 1, 0.5> } translate <2.5, 0.2, -2.5> }
|pov});
    ("mesh", {pov|#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> right x*4/3 }
light_source { <-5, 10, -6> color rgb 1 }
background { color rgb <0.3, 0.4, 0.6> }
plane { y, -0.5 pigment { rgb <0.7, 0.7, 0.6> } }
#declare Red = texture { pigment { rgb <1,0,0> } }
mesh {
  triangle { <-1,0,0>, <0,1.5,0>, <1,0,0> }
  triangle { <-1,0,0>, <0,0,-1>, <0,1.5,0> texture { Red } }
  smooth_triangle { <1,0,0>, <1,0,0>, <0,1.5,0>, <0,1,0>, <0,0,-1>, <0,0,-1> }
  pigment { rgb <0.2, 0.8, 0.3> }
  translate <-1.5, 0, 0>
}
mesh2 {
  vertex_vectors { 5, <-1,0,-1>, <1,0,-1>, <1,0,1>, <-1,0,1>, <0,1.5,0> }
  normal_vectors { 5, <-1,0.5,-1>, <1,0.5,-1>, <1,0.5,1>, <-1,0.5,1>, <0,1,0> }
  texture_list { 2, texture { pigment { rgb <0.9,0.9,0.2> } } texture { pigment { rgb <0.2,0.4,1> } } }
  face_indices { 4, <0,1,4>, 0, <1,2,4>, 1, <2,3,4>, 0, <3,0,4>, 1 }
  normal_indices { 4, <0,1,4>, <1,2,4>, <2,3,4>, <3,0,4> }
  pigment { rgb 1 }
  rotate y*20 translate <1.5, 0, 0>
}
torus { 1, 0.25 rotate x*85 translate <0, 0.6, 2> pigment { rgb <0.9,0.5,0.2> } finish { phong 1 } }
|pov});
    ("torus", {pov|#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.3, -8> look_at <0, 0, 0> right x*4/3 angle 40 }
light_source { <-5, 10, -6> color rgb 1 }
background { color rgb <0.3, 0.4, 0.6> }
torus { 2, 0.5 rotate x*3 pigment { rgb <0.9,0.5,0.2> } }
torus { 1000, 1 translate <0, -1.2, 1000> pigment { rgb <0.2,0.5,0.9> } }
torus { 0.5, 0.7 rotate z*90 translate <0, 1.6, 0> pigment { rgb <0.2,0.9,0.4> } }
|pov});
]

let exe () =
  match Sys.getenv_opt "CAMLRAY_EXE" with
  | Some e -> e
  | None ->
      let c = List.map (Filename.concat (Sys.getcwd ())) [ "../install/default/bin/camlray"; "../../install/default/bin/camlray" ] in
      Option.value ~default:(List.hd c) (List.find_opt Sys.file_exists c)

let have_povray () = Sys.command "command -v povray > /dev/null 2>&1" = 0

let run cmd = if Sys.command cmd <> 0 then Alcotest.failf "command failed: %s" cmd

let within2 (a : Image.rgb8) (b : Image.rgb8) =
  let n = a.w * a.h in
  let ok = ref 0 in
  for i = 0 to n - 1 do
    let good = ref true in
    for c = 0 to 2 do
      let x = Char.code (Bytes.get a.data ((3 * i) + c)) and y = Char.code (Bytes.get b.data ((3 * i) + c)) in
      if abs (x - y) > 2 then good := false
    done;
    if !good then incr ok
  done;
  float !ok /. float n

(* Render [src] (written into [dir]) with both and compare. *)
let compare_with_pov dir name src =
  let pov = Filename.concat dir (name ^ ".pov") in
  Out_channel.with_open_bin pov (fun oc -> output_string oc src);
  let ours = Filename.concat dir "ours.png" and theirs = Filename.concat dir "pov.png" in
  run (Printf.sprintf "%s render %s -W 160 -H 120 -q -o %s" (Filename.quote (exe ())) (Filename.quote pov)
         (Filename.quote ours));
  run (Printf.sprintf "cd %s && povray +I%s +O%s +W160 +H120 -D -A +FN > /dev/null 2>&1" (Filename.quote dir)
         (Filename.quote pov) (Filename.quote theirs));
  let a = Image.read ours and b = Image.read theirs in
  let frac = within2 a b and psnr = Metrics.psnr a b in
  if frac < 0.99 || psnr < 35. then begin
    Helpers.keep dir;
    Alcotest.failf "%s: %.2f%% of pixels within 2/255, PSNR %.1f dB (files in %s)" name (100. *. frac) psnr dir
  end

let case (name, src) =
  Alcotest.test_case ("camlray = POV-Ray: " ^ name) `Slow (fun () ->
      if not (have_povray ()) then Alcotest.skip ()
      else compare_with_pov (Helpers.temp_dir ~prefix:"camlray-geom" ()) name src)

(* obj2pov: a generated OBJ (quads, a group with normals, negative
   indices) converted and rendered by both. *)
let obj = {obj|# a cube with quads, and a smooth pyramid group
o cube
v -1 -1 -1
v 1 -1 -1
v 1 1 -1
v -1 1 -1
v -1 -1 1
v 1 -1 1
v 1 1 1
v -1 1 1
f 1 2 3 4
f 5 8 7 6
f 1 5 6 2
f 2 6 7 3
f 3 7 8 4
f 5 1 4 8
g pyramid
v 2 -1 -1
v 4 -1 -1
v 4 -1 1
v 2 -1 1
v 3 1 0
vn -1 0.5 -1
vn 1 0.5 -1
vn 1 0.5 1
vn -1 0.5 1
vn 0 1 0
f 9//1 10//2 13//5
f 10//2 11//3 13//5
f 11//3 12//4 13//5
f -2//4 -5//1 -1//5
|obj}

let obj_scene = {pov|#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1, 4, -8> look_at <1.5, 0, 0> right x*4/3 }
light_source { <-5, 10, -6> color rgb 1 }
background { color rgb <0.3, 0.4, 0.6> }
#include "t.inc"
object { OBJ_t_all pigment { rgb <0.9, 0.6, 0.3> } rotate y*20 }
object { OBJ_pyramid pigment { rgb <0.3, 0.6, 0.9> } translate <-3, 0, 2> }
|pov}

let obj2pov =
  Alcotest.test_case "obj2pov output renders the same in camlray and POV-Ray" `Slow (fun () ->
      let dir = Helpers.temp_dir ~prefix:"camlray-obj" () in
      let f name text = Out_channel.with_open_bin (Filename.concat dir name) (fun oc -> output_string oc text) in
      f "t.obj" obj;
      f "bad.obj" "v 0 0 0\nv 1 0 0\nf 1 2 3\n";
      run (Printf.sprintf "cd %s && %s obj2pov t.obj > t.inc" (Filename.quote dir) (Filename.quote (exe ())));
      let bad = Sys.command (Printf.sprintf "cd %s && %s obj2pov bad.obj > /dev/null 2> err.txt" (Filename.quote dir)
                               (Filename.quote (exe ()))) in
      Alcotest.(check int) "bad OBJ: exit 1" 1 bad;
      let err = In_channel.with_open_bin (Filename.concat dir "err.txt") In_channel.input_all in
      Alcotest.(check string) "located message"
        "camlray obj2pov: bad.obj:3: error: vertex index \"3\" out of range (1..2)\n" err;
      f "scene.pov" obj_scene;
      if have_povray () then compare_with_pov dir "scene" obj_scene
      else run (Printf.sprintf "%s check %s" (Filename.quote (exe ())) (Filename.quote (Filename.concat dir "scene.pov"))))

let tests = ("geometry vs POV-Ray", List.map case scenes @ [ obj2pov ])
