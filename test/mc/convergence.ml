(* Long Monte Carlo checks, too slow for the test suite: RMSE against a
   high-spp reference over a range of spp (slope of log RMSE against
   log spp, expected -1/2), and the emitting enclosure to 0.2 %.
   Usage: convergence.exe [domains] *)
open Camlray
open Camlray_lang

let compile text =
  match Parse.string ~name:"convergence.scn" text with
  | Error d -> failwith (Diag.to_string d)
  | Ok s -> ( match Compile.scene s with Error d -> failwith (Diag.to_string d) | Ok s -> s)

let domains = if Array.length Sys.argv > 1 then int_of_string Sys.argv.(1) else 2

let render ?(seed = 1) ~w ~h ~spp ~depth scene =
  let t = Path.prepare scene in
  Render.image ~domains ~width:w ~height:h (Path.pixel t ~width:w ~height:h ~seed ~spp ~max_depth:depth)

let rmse a b =
  let s = ref 0. and n = ref 0 in
  for y = 0 to Image.height a - 1 do
    for x = 0 to Image.width a - 1 do
      List.iter
        (fun get ->
          s := !s +. ((get a x y -. get b x y) ** 2.);
          incr n)
        [ Image.get_r; Image.get_g; Image.get_b ]
    done
  done;
  Float.sqrt (!s /. float !n)

let mean img =
  let s = ref 0. in
  for y = 0 to Image.height img - 1 do
    for x = 0 to Image.width img - 1 do
      s := !s +. Image.get_r img x y
    done
  done;
  !s /. float (Image.width img * Image.height img)

let scene =
  compile
    "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n\
     camera { location <0,1.5,-4> look_at <0,0.5,0> angle 50 }\n\
     sphere { <1, 2.2, 0>, 0.5 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 4 } }\n\
     plane { y, 0 pigment { rgb 0.7 } finish { ambient 0 diffuse 1 } }\n\
     sphere { <-0.5, 0.7, 0.5>, 0.7 pigment { rgb <0.8,0.3,0.2> }\n\
    \  finish { ambient 0 diffuse 0.7 specular 0.3 roughness 0.02 } }\n\
     sphere { <1.2, 0.5, -0.5>, 0.5 pigment { rgbf <1,1,1,1> } finish { ambient 0 diffuse 0 }\n\
    \  interior { ior 1.5 } }\n\
     background { rgb <0.3, 0.4, 0.5> }\n"

let () =
  let w = 32 and h = 24 in
  let t0 = Unix.gettimeofday () in
  let reference = render ~seed:1000 ~w ~h ~spp:16384 ~depth:16 scene in
  Printf.printf "reference: %dx%d at 16384 spp in %.1f s\n%!" w h (Unix.gettimeofday () -. t0);
  let pts =
    List.map
      (fun spp ->
        let e = rmse (render ~seed:7 ~w ~h ~spp ~depth:16 scene) reference in
        Printf.printf "spp %5d  RMSE %.5f\n%!" spp e;
        (Float.log (float spp), Float.log e))
      [ 2; 8; 32; 128; 512 ]
  in
  let n = float (List.length pts) in
  let sx = List.fold_left (fun a (x, _) -> a +. x) 0. pts
  and sy = List.fold_left (fun a (_, y) -> a +. y) 0. pts in
  let sxx = List.fold_left (fun a (x, _) -> a +. (x *. x)) 0. pts
  and sxy = List.fold_left (fun a (x, y) -> a +. (x *. y)) 0. pts in
  Printf.printf "slope of log RMSE vs log spp: %.3f (expected -0.5)\n%!"
    (((n *. sxy) -. (sx *. sy)) /. ((n *. sxx) -. (sx *. sx)));
  List.iter
    (fun (a, expected) ->
      let s =
        compile
          (Printf.sprintf
             "#version 3.7;\ncamera { location 0 look_at z }\n\
              sphere { 0, 1 pigment { rgb 1 } finish { ambient 0 diffuse %g emission 0.5 } }\n"
             a)
      in
      let m = mean (render ~w:16 ~h:16 ~spp:1024 ~depth:256 s) in
      Printf.printf "enclosure a=%g Le=0.5: %.4f (expected %g, error %.2f%%)\n%!" a m expected
        (100. *. Float.abs (m -. expected) /. expected))
    [ (0.5, 1.); (0.9, 5.) ]
