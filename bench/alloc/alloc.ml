(* Minor words allocated per camera ray, measured with Gc.quick_stat
   around a one-domain render (whitted: one ray per pixel; mc: per sample).
   Usage: alloc.exe SCENE... [-W n] [-H n] [--mc SPP] *)
open Camlray

let () =
  let w = ref 160 and h = ref 120 and mc = ref 0 and files = ref [] in
  Arg.parse
    [ ("-W", Arg.Set_int w, "width"); ("-H", Arg.Set_int h, "height");
      ("--mc", Arg.Set_int mc, "SPP measure mc mode with SPP samples per pixel") ]
    (fun f -> files := f :: !files)
    "alloc.exe SCENE...";
  Printf.printf "| scene | mode | camera rays | minor words per camera ray |\n|---|---|---|---|\n";
  List.iter
    (fun file ->
      match Camlray_lang.Parse.file file with
      | Error d -> prerr_string (Camlray_lang.Diag.to_string d)
      | Ok (sdl, _) -> (
          match Camlray_lang.Compile.scene sdl with
          | Error d -> prerr_string (Camlray_lang.Diag.to_string d)
          | Ok s ->
              let width = !w and height = !h in
              let pixel, rays, mode =
                if !mc > 0 then
                  ( Path.pixel (Path.prepare s) ~width ~height ~seed:0 ~spp:!mc ~max_depth:16,
                    width * height * !mc, Printf.sprintf "mc %d spp" !mc )
                else (Whitted.pixel s ~width ~height, width * height, "whitted")
              in
              let before = Gc.minor_words () in
              ignore (Render.image ~domains:1 ~width ~height pixel);
              let words = Gc.minor_words () -. before in
              Printf.printf "| %s | %s | %d | %.1f |\n%!" (Filename.basename file) mode rays
                (words /. float rays)))
    (List.rev !files)
