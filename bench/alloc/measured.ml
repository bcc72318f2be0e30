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

(* as [camlray render] runs it: written into the tile's sum *)
let pixel (s : Scene.t) ~width ~height ~mc =
  if mc > 0 then begin
    let f = Path.pixel (Path.prepare s) ~width ~height ~seed:0 ~spp:mc ~max_depth:16 in
    fun x y (out : Color.acc) ->
      let c : Color.t = f x y in
      Color.acc_set out c.r c.g c.b
  end
  else Whitted.pixel_into s ~width ~height
