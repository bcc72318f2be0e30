(* Every bundled scene must also render in POV-Ray 3.7 (checked where
   POV-Ray is installed), and camlray's default scene must agree with
   POV-Ray's picture of it. *)
let povray_available () = Sys.command "command -v povray >/dev/null 2>&1" = 0

let rec scenes dir =
  Sys.readdir dir |> Array.to_list |> List.sort compare
  |> List.concat_map (fun f ->
         let p = Filename.concat dir f in
         if Sys.is_directory p then scenes p
         else if Filename.check_suffix f ".scn" then [ p ]
         else [])

let povray ~scene ~out ~w ~h extra =
  Printf.sprintf "povray +I%s +O%s +W%d +H%d -D +FN %s -GA -V >/dev/null 2>&1"
    (Filename.quote scene) (Filename.quote out) w h extra

let tests =
  ( "povray",
    [
      Alcotest.test_case "every scene in scenes/ renders in POV-Ray" `Slow (fun () ->
          if not (povray_available ()) then Printf.printf "POV-Ray not installed: skipped\n"
          else
            let d = Helpers.temp_dir () in
            List.iter
              (fun scene ->
                let out = Filename.concat d "p.png" in
                if Sys.file_exists out then Sys.remove out;
                let code = Sys.command (povray ~scene ~out ~w:32 ~h:24 "-A") in
                if code <> 0 || not (Sys.file_exists out) then
                  Alcotest.failf "POV-Ray failed on %s (exit %d)" scene code)
              (scenes (Helpers.scenes_dir ())));
      Alcotest.test_case "default scene: camlray and POV-Ray agree (PSNR >= 40 dB, 320x240, no AA)" `Slow
        (fun () ->
          if not (povray_available ()) then Printf.printf "POV-Ray not installed: skipped\n"
          else
            let d = Helpers.temp_dir () in
            let pov = Filename.concat d "pov.png" and ours = Filename.concat d "ours.png" in
            let scene = Filename.concat (Helpers.scenes_dir ()) "default.scn" in
            let code = Sys.command (povray ~scene ~out:pov ~w:320 ~h:240 "-A") in
            Alcotest.(check int) "povray" 0 code;
            let c, _, err = Helpers.run [ "render"; scene; "-W"; "320"; "-H"; "240"; "-o"; ours; "-q" ] in
            Alcotest.(check int) ("camlray: " ^ err) 0 c;
            let a = Camlray.Image.read pov and b = Camlray.Image.read ours in
            let psnr = Camlray.Metrics.psnr a b and ssim = Camlray.Metrics.ssim a b in
            Printf.printf "default scene vs POV-Ray: PSNR %.2f dB, SSIM %.5f\n" psnr ssim;
            if psnr < 40. then Alcotest.failf "PSNR %.2f dB < 40" psnr;
            if ssim < 0.99 then Alcotest.failf "SSIM %.5f < 0.99" ssim);
    ] )
