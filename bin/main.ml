(* camlray's command line: argument parsing and exit codes only; the work
   is done by Driver. *)
open Cmdliner

let exit_misuse = 2

let mode_conv =
  Arg.enum [ ("whitted", Driver.Whitted); ("mc", Driver.Monte_carlo) ]

let include_path =
  Arg.(value & opt_all dir [] & info [ "include-path"; "L" ] ~docv:"DIR"
         ~doc:"Also search $(docv) for $(b,#include) files (after the current folder and \
               the scene's folder, before POV-Ray's include folder). Repeatable.")

let scene_arg =
  Arg.(value & pos 0 (some string) None & info [] ~docv:"SCENE"
         ~doc:"The scene file ($(b,.scn) or $(b,.pov)). Without it, camlray renders its \
               built-in default scene.")

let aa_args =
  let aa =
    Arg.(value & opt (some float) None & info [ "aa" ] ~docv:"THRESHOLD"
           ~doc:"Anti-alias as POV-Ray's $(b,+A)$(docv) (sampling method 1, no jitter): \
                 supersample pixels whose gamma-encoded colour differs from a neighbour's by \
                 at least $(docv) (POV-Ray's default is 0.3). Off when absent. Whitted mode only.")
  in
  let depth =
    Arg.(value & opt int 3 & info [ "aa-depth" ] ~docv:"N"
           ~doc:"Supersample with an $(docv) x $(docv) grid plus the centre (POV-Ray's \
                 $(b,+R)$(docv)), 1 to 9.")
  in
  Term.(const (fun a d -> (a, d)) $ aa $ depth)

let render_cmd =
  let output =
    Arg.(value & opt (some string) None & info [ "o"; "output" ] ~docv:"OUT"
           ~doc:"Write the image to $(docv): PNG, or PPM when it ends in $(b,.ppm), or a \
                 linear float PFM when it ends in $(b,.pfm). Default: the scene's base \
                 name with $(b,.png), in the current folder. Written atomically.")
  in
  let width = Arg.(value & opt int 800 & info [ "W"; "width" ] ~docv:"PIXELS" ~doc:"Image width.") in
  let height = Arg.(value & opt int 600 & info [ "H"; "height" ] ~docv:"PIXELS" ~doc:"Image height.") in
  let mode =
    Arg.(value & opt mode_conv Driver.Whitted & info [ "mode"; "m" ] ~docv:"MODE"
           ~doc:"$(b,whitted): POV-Ray's classic model (Blinn-Phong, shadows, reflection, \
                 refraction), the same picture POV-Ray makes. $(b,mc): an unbiased Monte \
                 Carlo path tracer on the same scene.")
  in
  let spp =
    Arg.(value & opt int 64 & info [ "spp" ] ~docv:"N"
           ~doc:"Samples per pixel in $(b,mc) mode (ignored, with a warning, in whitted mode).")
  in
  let depth =
    Arg.(value & opt (some int) None & info [ "depth" ] ~docv:"N"
           ~doc:"Maximum ray depth. Default: the scene's $(b,max_trace_level) (5 unless set) \
                 in whitted mode, 16 in mc mode.")
  in
  let domains =
    Arg.(value & opt (some int) None & info [ "domains"; "j" ] ~docv:"N"
           ~doc:"Render on $(docv) domains (default: the number of cores).")
  in
  let seed = Arg.(value & opt int 0 & info [ "seed" ] ~docv:"N" ~doc:"Random seed (mc mode).") in
  let quiet = Arg.(value & flag & info [ "quiet"; "q" ] ~doc:"Print nothing but errors.") in
  let run scene output width height mode spp depth domains seed quiet include_dirs (aa, aa_depth) =
    Driver.render
      { Driver.scene; output; width; height; mode; spp; depth; domains; seed; quiet; include_dirs;
        aa; aa_depth }
  in
  let term =
    Term.(const run $ scene_arg $ output $ width $ height $ mode $ spp $ depth $ domains $ seed
          $ quiet $ include_path $ aa_args)
  in
  let man =
    [ `S Manpage.s_description;
      `P "Renders a scene written in POV-Ray 3.7's scene description language (the subset \
          camlray supports) to an image.";
      `S Manpage.s_examples;
      `Pre "  camlray render scenes/default.scn -W 320 -H 240 -o small.png\n\
           \  camlray render scene.scn --mode mc --spp 256 -o scene-mc.png";
      `S Manpage.s_exit_status;
      `P "0 on success; 1 for an error in the scene, a file or a value; 2 for misuse of the \
          command line; 130 when interrupted." ]
  in
  Cmd.v (Cmd.info "render" ~doc:"Render a scene to an image." ~man) term

let check_cmd =
  let scene = Arg.(required & pos 0 (some string) None & info [] ~docv:"SCENE" ~doc:"The scene file.") in
  Cmd.v
    (Cmd.info "check" ~doc:"Parse and compile a scene, report errors, render nothing.")
    Term.(const Driver.check $ scene $ include_path)

let main =
  let man =
    [ `S Manpage.s_description;
      `P "camlray is a multicore ray tracer for scenes written in POV-Ray 3.7's scene \
          description language.";
      `S Manpage.s_examples;
      `Pre "  camlray render scenes/default.scn -o out.png\n  camlray check scene.scn" ]
  in
  Cmd.group (Cmd.info "camlray" ~version:"0.1.0" ~doc:"multicore ray tracer for POV-Ray scenes" ~man)
    [ render_cmd; check_cmd; Compare.cmd ~aa_args ~include_path ]

let () =
  let err_buf = Buffer.create 256 in
  let err = Format.formatter_of_buffer err_buf in
  match Cmd.eval_value ~err main with
  | Ok (`Ok code) -> exit code
  | Ok (`Version | `Help) -> exit 0
  | Error _ ->
      Format.pp_print_flush err ();
      let text = Buffer.contents err_buf in
      let first =
        match List.filter (fun l -> String.trim l <> "") (String.split_on_char '\n' text) with
        | l :: _ -> String.trim l
        | [] -> "invalid command line"
      in
      let first =
        if String.length first > 8 && String.sub first 0 8 = "camlray:" then first
        else "camlray: " ^ first
      in
      prerr_endline (first ^ " (see 'camlray --help')");
      exit exit_misuse
