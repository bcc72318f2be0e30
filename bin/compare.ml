(* Cross-render harness: POV-Ray against camlray on the same scenes. *)
open Camlray

let povray_available () = Sys.command "command -v povray >/dev/null 2>&1" = 0

let is_scene f =
  match String.lowercase_ascii (Filename.extension f) with ".pov" | ".scn" -> true | _ -> false

let expand inputs =
  List.concat_map
    (fun p ->
      if Sys.file_exists p && Sys.is_directory p then
        Sys.readdir p |> Array.to_list |> List.filter is_scene |> List.sort compare
        |> List.map (Filename.concat p)
      else [ p ])
    inputs

let time f =
  let t0 = Unix.gettimeofday () in
  let r = f () in
  (r, Unix.gettimeofday () -. t0)

(* POV-Ray run on [scene]; [`Done ok], or [`Late] when it ran past
   [limit] seconds (it is killed then) *)
let povray ~scene ~out ~log ~width ~height ~aa ~aa_depth ~limit =
  let aa_opts =
    match aa with
    | Some t -> [ Printf.sprintf "+A%g" t; "+AM1"; Printf.sprintf "+R%d" aa_depth; "-J" ]
    | None -> [ "-A" ]
  in
  let args =
    [ "povray"; "+I" ^ scene; "+O" ^ out; Printf.sprintf "+W%d" width; Printf.sprintf "+H%d" height;
      "-D"; "-P"; "+FN"; "-UA"; "+L" ^ Filename.dirname scene ]
    @ aa_opts
  in
  let fd = Unix.openfile log [ Unix.O_WRONLY; Unix.O_CREAT; Unix.O_TRUNC; Unix.O_CLOEXEC ] 0o644 in
  let pid =
    Fun.protect ~finally:(fun () -> Unix.close fd) (fun () ->
        Unix.create_process "povray" (Array.of_list args) Unix.stdin fd fd)
  in
  let deadline = match limit with Some s -> Unix.gettimeofday () +. s | None -> infinity in
  let rec wait () =
    match Unix.waitpid [ Unix.WNOHANG ] pid with
    | 0, _ ->
        if Unix.gettimeofday () > deadline then begin
          Unix.kill pid Sys.sigkill;
          ignore (Unix.waitpid [] pid);
          `Late
        end
        else begin
          Unix.sleepf 0.02;
          wait ()
        end
    | _, Unix.WEXITED 0 -> `Done (Sys.file_exists out)
    | _, _ -> `Done false
    | exception Unix.Unix_error (Unix.EINTR, _, _) -> wait ()
  in
  wait ()

(* Scenes whose pictures depend on POV-Ray's random sampling (jittered
   area lights, focal blur's lens samples, radiosity's gathers and where
   its cache keeps them, crand's grain, photons: each ring of directions
   starts at a random angle, even with jitter 0), so they cannot match
   pixel for pixel: reported separately. Noise patterns are POV-Ray's own
   and are held to the same standard as any other scene. *)
let noise_words = [ "jitter"; "aperture"; "radiosity"; "crand"; "photons" ]

let has_noise_word text =
  let words =
    String.split_on_char ' '
      (String.map (fun c -> match c with 'a' .. 'z' | '0' .. '9' | '_' | '.' -> c | _ -> ' ') text)
  in
  List.exists (fun w -> List.mem w noise_words) words

(* the scene and the files of its own it includes (as the parser reads
   them, at the size compared: a scene may loop over its pixels); POV-Ray's
   standard include files count by name (woods.inc, ...) where they are
   included, not by everything they declare *)
let uses_noise ~include_dirs ~width ~height file =
  let options = { Camlray_lang.Parse.default_options with include_dirs; image_width = width; image_height = height } in
  let files =
    match Camlray_lang.Parse.file ~options file with
    | Ok (_, files) -> files
    | Error _ -> [ file ]
  in
  let standard f = String.starts_with ~prefix:Camlray_lang.Parse.pov_include_dir f in
  List.exists
    (fun f ->
      match In_channel.with_open_bin f In_channel.input_all with
      | exception Sys_error _ -> false
      | text -> has_noise_word text)
    (List.filter (fun f -> not (standard f)) files)

type row = {
  name : string;
  noise : bool;
  psnr : float;
  ssim : float;
  max_diff : int;
  pov_s : float;
  cam_s : float;
  note : string;
}

let fmt_psnr p = if p = infinity then "inf" else Printf.sprintf "%.2f" p

let write_report out_dir ~width ~height ~aa ~aa_depth rows =
  let md = Buffer.create 1024 and tsv = Buffer.create 1024 in
  Printf.bprintf md "# camlray vs POV-Ray\n\n%d x %d, %s\n\n" width height
    (match aa with
    | Some t -> Printf.sprintf "anti-aliasing +A%g +AM1 +R%d -J (camlray --aa %g --aa-depth %d)" t aa_depth t aa_depth
    | None -> "anti-aliasing off (-A)");
  Buffer.add_string md
    "| scene | PSNR dB | SSIM | max diff | POV-Ray s | camlray s | side by side (POV-Ray, camlray, diff) |\n\
     |---|---|---|---|---|---|---|\n";
  Buffer.add_string tsv "scene\tpsnr\tssim\tmax_diff\tpovray_s\tcamlray_s\trandom\n";
  List.iter
    (fun r ->
      if r.note <> "" then begin
        Printf.bprintf md "| %s | - | - | - | %.2f | %.2f | %s |\n" r.name r.pov_s r.cam_s r.note;
        Printf.bprintf tsv "%s\tnan\tnan\t-1\t%.3f\t%.3f\t%b\n" r.name r.pov_s r.cam_s r.noise
      end
      else begin
        Printf.bprintf md "| %s%s | %s | %.4f | %d | %.2f | %.2f | ![](%s.side.png) |\n" r.name
          (if r.noise then " (random)" else "")
          (fmt_psnr r.psnr) r.ssim r.max_diff r.pov_s r.cam_s r.name;
        Printf.bprintf tsv "%s\t%s\t%.5f\t%d\t%.3f\t%.3f\t%b\n" r.name (fmt_psnr r.psnr) r.ssim
          r.max_diff r.pov_s r.cam_s r.noise
      end)
    rows;
  let summary label rows =
    let rs = List.filter (fun r -> r.note = "") rows in
    if rs <> [] then begin
      let n = float_of_int (List.length rs) in
      let mean f = List.fold_left (fun a r -> a +. f r) 0. rs /. n in
      let worst = List.fold_left (fun a r -> Float.min a r.ssim) 1. rs in
      Printf.bprintf md "\n%s: %d scenes, mean SSIM %.4f, lowest SSIM %.4f\n" label (List.length rs)
        (mean (fun r -> r.ssim)) worst
    end
  in
  summary "Scenes without random sampling (expected to match)" (List.filter (fun r -> not r.noise) rows);
  summary "Scenes with random sampling (reported separately)"
    (List.filter (fun r -> r.noise) rows);
  let write name b =
    Image.write_atomic (Filename.concat out_dir name) (fun oc -> Buffer.output_buffer oc b)
  in
  write "report.md" md;
  write "report.tsv" tsv

let run ~inputs ~width ~height ~aa ~aa_depth ~out_dir ~include_dirs ~limit =
  (* SSIM looks through an 11x11 window *)
  if width < 11 || height < 11 then begin
    Printf.eprintf "camlray compare: error: images of at least 11x11 pixels are compared (SSIM's window), not %dx%d\n"
      width height;
    1
  end
  else if not (povray_available ()) then begin
    print_endline "camlray compare: povray is not installed (not on PATH); nothing was compared";
    0
  end
  else begin
    let rec mkdir_p d =
      if not (Sys.file_exists d) then begin
        mkdir_p (Filename.dirname d);
        try Unix.mkdir d 0o755 with Unix.Unix_error (Unix.EEXIST, _, _) -> ()
      end
    in
    mkdir_p out_dir;
    let scenes = expand inputs in
    if scenes = [] then prerr_endline "camlray compare: no scenes (.pov or .scn) given";
    let ok = ref (scenes <> []) in
    let rows =
      List.map
        (fun scene ->
          let name = Filename.remove_extension (Filename.basename scene) in
          let path suffix = Filename.concat out_dir (name ^ suffix) in
          let pov_png = path ".povray.png" and cam_png = path ".camlray.png" in
          let pov_run, pov_s =
            time (fun () ->
                povray ~scene ~out:pov_png ~log:(path ".povray.log") ~width ~height ~aa ~aa_depth ~limit)
          in
          let render () =
            Driver.with_time_limit limit (fun () ->
                Driver.render
                  { Driver.scene = Some scene; output = Some cam_png; width; height;
                    mode = Driver.Whitted; spp = None; depth = None; domains = None; seed = 0;
                    quiet = true; include_dirs; allow_read = []; region = None; pov_region = None;
                    frames = None; clock = None; clock_range = None; subset = None;
                    tile_order_seed = None; aa; aa_depth; limits = Camlray_lang.Supplier.default_limits })
          in
          (* nothing to compare with when POV-Ray ran past the limit *)
          let cam_code, cam_s = if pov_run = `Late then (0, 0.) else time render in
          let noise = uses_noise ~include_dirs ~width ~height scene in
          let row note = { name; noise; psnr = nan; ssim = nan; max_diff = -1; pov_s; cam_s; note } in
          let r =
            let late = Printf.sprintf "ran past the %g s limit" (Option.value limit ~default:0.) in
            if pov_run = `Late then row ("POV-Ray " ^ late)
            else if pov_run = `Done false then row (Printf.sprintf "POV-Ray failed (see %s.povray.log)" name)
            else if cam_code = 130 && limit <> None then row ("camlray " ^ late)
            else if cam_code <> 0 then row "camlray failed"
            else
              let a = Image.read pov_png and b = Image.read cam_png in
              if a.w <> b.w || a.h <> b.h then row "image sizes differ"
              else begin
                let d = Metrics.diff_image a b in
                Image.write_png (path ".diff.png") d;
                Image.write_png (path ".side.png") (Metrics.side_by_side [ a; b; d ]);
                { name; noise; psnr = Metrics.psnr a b; ssim = Metrics.ssim a b; max_diff = Metrics.max_diff a b;
                  pov_s; cam_s; note = "" }
              end
          in
          if r.note <> "" then ok := false;
          Printf.printf "%-28s %s%s\n%!" name (if noise then "(random) " else "")
            (if r.note <> "" then r.note
             else Printf.sprintf "PSNR %s dB  SSIM %.4f  max diff %d  (POV-Ray %.2f s, camlray %.2f s)"
                 (fmt_psnr r.psnr) r.ssim r.max_diff pov_s cam_s);
          r)
        scenes
    in
    write_report out_dir ~width ~height ~aa ~aa_depth rows;
    Printf.printf "report: %s\n" (Filename.concat out_dir "report.md");
    if !ok then 0 else 1
  end

let cmd ~aa_args ~include_path =
  let open Cmdliner in
  let inputs =
    Arg.(non_empty & pos_all string [] & info [] ~docv:"SCENE|DIR"
           ~doc:"Scene files, or folders whose $(b,.pov) and $(b,.scn) files are all compared.")
  in
  let width = Arg.(value & opt int 160 & info [ "W"; "width" ] ~docv:"PIXELS" ~doc:"Image width.") in
  let height = Arg.(value & opt int 120 & info [ "H"; "height" ] ~docv:"PIXELS" ~doc:"Image height.") in
  let out =
    Arg.(value & opt string "compare-report" & info [ "o"; "output" ] ~docv:"DIR"
           ~doc:"Folder for the report, the renders and the side-by-side and difference images.")
  in
  let limit =
    Arg.(value & opt (some float) None & info [ "time-limit" ] ~docv:"SECONDS"
           ~doc:"Give each renderer at most $(docv) seconds a scene: POV-Ray is stopped, camlray's render \
                 cancelled, and the scene reported as ran past the limit (and the exit status is 1).")
  in
  let run inputs width height (aa, aa_depth) out_dir include_dirs limit =
    match limit with
    | Some s when not (s > 0.) ->
        Printf.eprintf "camlray compare: error: --time-limit must be a positive number of seconds, not %g\n" s;
        1
    | _ -> run ~inputs ~width ~height ~aa ~aa_depth ~out_dir ~include_dirs ~limit
  in
  Cmd.v
    (Cmd.info "compare"
       ~doc:"Render scenes with POV-Ray and camlray and report how far apart the images are.")
    Term.(const run $ inputs $ width $ height $ aa_args $ out $ include_path $ limit)
