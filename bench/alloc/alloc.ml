(* Minor words allocated per camera ray, measured with Gc.minor_words
   around a one-domain render (whitted: one ray per pixel; mc: per sample),
   the second of two (the first, reported beside it, makes the domain's
   scratch),
   and for the traversal and intersection kernel alone: Scene.nearest on
   precomputed camera rays (no shading), with its speed.
   Usage: alloc.exe SCENE... [-W n] [-H n] [--mc SPP] *)
open Camlray

let () =
  let w = ref 160 and h = ref 120 and mc = ref 0 and files = ref [] in
  Arg.parse
    [ ("-W", Arg.Set_int w, "width"); ("-H", Arg.Set_int h, "height");
      ("--mc", Arg.Set_int mc, "SPP measure mc mode with SPP samples per pixel") ]
    (fun f -> files := f :: !files)
    "alloc.exe SCENE...";
  Printf.printf
    "| scene | mode | camera rays | minor words per camera ray | first render |\n|---|---|---|---|---|\n";
  List.iter
    (fun file ->
      match Measured.load file with
      | Error msg -> prerr_string msg
      | Ok s -> (
          let width = !w and height = !h in
          let pixel = Measured.pixel s ~width ~height ~mc:!mc in
          let rays, mode =
            if !mc > 0 then (width * height * !mc, Printf.sprintf "mc %d spp" !mc)
            else (width * height, "whitted")
          in
          (* the first render makes the domain's scratch (per object for
             some: an isosurface's frame); the second is what a ray costs *)
          let before = Gc.minor_words () in
          ignore (Render.image_into ~domains:1 ~width ~height pixel);
          let first = Gc.minor_words () -. before in
          let before = Gc.minor_words () in
          ignore (Render.image_into ~domains:1 ~width ~height pixel);
          let words = Gc.minor_words () -. before in
          Printf.printf "| %s | %s | %d | %.1f | %.1f |\n%!" (Filename.basename file) mode rays
            (words /. float rays) (first /. float rays);
          (* the kernel: nearest hit of every camera ray, nothing else *)
          let rays = Camlray_bench.Bench.camera_rays s ~width ~height in
          let pass = Camlray_bench.Bench.nearest_pass s rays in
          ignore (pass ());
          let reps = 20 in
          let before = Gc.minor_words () and t0 = Unix.gettimeofday () in
          for _ = 1 to reps do ignore (pass ()) done;
          let dt = Unix.gettimeofday () -. t0 and words = Gc.minor_words () -. before in
          let n = float (reps * Array.length rays) in
          Printf.printf "| %s | kernel: Scene.nearest only | %d | %.2f (%.2f M rays/s) | |\n%!"
            (Filename.basename file) (reps * Array.length rays) (words /. n) (n /. dt /. 1e6);
          (* the same through the public query, which builds the hit record *)
          let before = Gc.minor_words () and t0 = Unix.gettimeofday () in
          for _ = 1 to reps do
            Array.iter (fun ray -> ignore (Sys.opaque_identity (Scene.intersect s ray 0. infinity))) rays
          done;
          let dt = Unix.gettimeofday () -. t0 and words = Gc.minor_words () -. before in
          Printf.printf "| %s | kernel: Scene.intersect | %d | %.2f (%.2f M rays/s) | |\n%!"
            (Filename.basename file) (reps * Array.length rays) (words /. n) (n /. dt /. 1e6)))
    (List.rev !files)
