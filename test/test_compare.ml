(* The cross-render harness: camlray against POV-Ray on a fixed list of
   simple scenes at 160x120 (runs only where povray is installed). *)

let exe () =
  match Sys.getenv_opt "CAMLRAY_EXE" with
  | Some e -> e
  | None -> "../install/default/bin/camlray"

let scenes_dir = "../../../scenes/whitted-extra"

(* scene, minimum SSIM, minimum PSNR (dB), with anti-aliasing +A0.3 +R3 -J
   (noise.pov is left out: camlray's noise is not POV-Ray's) *)
let expectations =
  [ ("checker", 0.98, 50.); ("area", 0.98, 50.); ("layered", 0.98, 50.); ("sky", 0.98, 50.);
    ("backdiffuse", 0.98, 50.); ("fadeshadow", 0.98, 50.); ("glass", 0.98, 50.);
    ("lights", 0.98, 50.); ("patterns", 0.98, 50.); ("normals", 0.98, 50.); ("texmap", 0.98, 50.) ]

let read_tsv file =
  let ic = open_in file in
  Fun.protect ~finally:(fun () -> close_in ic) (fun () ->
      ignore (input_line ic);
      let rec go acc =
        match input_line ic with
        | l -> (
            match String.split_on_char '\t' l with
            | name :: psnr :: ssim :: _ ->
                let psnr = if psnr = "inf" then infinity else float_of_string psnr in
                go ((name, (psnr, float_of_string ssim)) :: acc)
            | _ -> go acc)
        | exception End_of_file -> acc
      in
      go [])

let cross_render () =
  if Sys.command "command -v povray >/dev/null 2>&1" <> 0 then
    print_endline "povray not installed: cross-render test skipped"
  else begin
    let out = Filename.concat (Filename.get_temp_dir_name ()) (Printf.sprintf "camlray-compare-%d" (Unix.getpid ())) in
    let files = List.map (fun (n, _, _) -> Filename.quote (Filename.concat scenes_dir (n ^ ".pov"))) expectations in
    let cmd =
      Printf.sprintf "%s compare -W 160 -H 120 --aa 0.3 -o %s %s >/dev/null 2>&1" (Filename.quote (exe ()))
        (Filename.quote out) (String.concat " " files)
    in
    Alcotest.(check int) "compare exit code" 0 (Sys.command cmd);
    let rows = read_tsv (Filename.concat out "report.tsv") in
    List.iter
      (fun (name, min_ssim, min_psnr) ->
        match List.assoc_opt name rows with
        | None -> Alcotest.failf "%s missing from the report" name
        | Some (psnr, ssim) ->
            if not (ssim >= min_ssim) then Alcotest.failf "%s: SSIM %.4f below %.2f" name ssim min_ssim;
            if not (psnr >= min_psnr) then Alcotest.failf "%s: PSNR %.2f dB below %.0f" name psnr min_psnr)
      expectations;
    ignore (Sys.command ("rm -rf " ^ Filename.quote out))
  end

let skips () =
  (* without povray on PATH the command says so and succeeds *)
  let cmd =
    Printf.sprintf "PATH=/nonexistent %s compare %s/checker.pov -o /tmp/camlray-nopov-%d" (Filename.quote (exe ()))
      scenes_dir (Unix.getpid ())
  in
  let ic = Unix.open_process_in cmd in
  let line = try input_line ic with End_of_file -> "" in
  let status = Unix.close_process_in ic in
  Alcotest.(check bool) "exit 0" true (status = Unix.WEXITED 0);
  Alcotest.(check bool) "says povray is not installed" true
    (try ignore (Str.search_forward (Str.regexp_string "not installed") line 0); true with Not_found -> false)

let tests =
  ( "compare",
    [
      Alcotest.test_case "camlray vs POV-Ray" `Slow cross_render;
      Alcotest.test_case "skips without povray" `Quick skips;
    ] )
