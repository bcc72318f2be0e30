(* What alloc.exe and sites.exe both measure: a scene file compiled, and
   its pixel function in whitted mode or, with [mc] samples per pixel, in
   Monte Carlo mode. *)
open Camlray

let load file =
  match Camlray_lang.Parse.file file with
  | Error d -> Error (Camlray_lang.Diag.to_string d)
  | Ok (sdl, _) -> (
      match Camlray_lang.Compile.scene sdl with
      | Error d -> Error (Camlray_lang.Diag.to_string d)
      | Ok s -> Ok s)

(* as [camlray render] runs it: written into the tile's sum (with
   radiosity, after its pretrace) *)
let pixel (s : Scene.t) ~width ~height ~mc =
  if mc > 0 then Path.pixel_into (Path.prepare s) ~width ~height ~seed:0 ~spp:mc ~max_depth:16
  else begin
    (* radiosity's pretrace first, as [camlray render] runs it *)
    Whitted.prepare s ~width ~height;
    Whitted.pixel_into s ~width ~height
  end
