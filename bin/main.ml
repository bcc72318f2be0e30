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

let limits =
  let d = Camlray_lang.Supplier.default_limits in
  let max_loop =
    Arg.(value & opt int d.max_loop_iterations & info [ "max-loop" ] ~docv:"N"
           ~doc:"Stop a $(b,#while) or $(b,#for) loop with an error after $(docv) iterations.")
  in
  let max_macro =
    Arg.(value & opt int d.max_macro_depth & info [ "max-macro-depth" ] ~docv:"N"
           ~doc:"Stop with an error when macro calls nest deeper than $(docv).")
  in
  let max_array =
    Arg.(value & opt int d.max_array_size & info [ "max-array" ] ~docv:"N"
           ~doc:"Refuse arrays of more than $(docv) elements.")
  in
  let max_objects =
    Arg.(value & opt int d.max_objects & info [ "max-objects" ] ~docv:"N"
           ~doc:"Stop with an error when the scene makes more than $(docv) objects (every \
                 shape and CSG read, and every node of the objects placed in the scene).")
  in
  Term.(const (fun l m a o ->
      { d with Camlray_lang.Supplier.max_loop_iterations = max 1 l; max_macro_depth = max 1 m;
               max_array_size = max 1 a; max_objects = max 1 o })
        $ max_loop $ max_macro $ max_array $ max_objects)

let allow_read =
  Arg.(value & opt_all dir [] & info [ "allow-read" ] ~docv:"DIR"
         ~doc:"Let the scene read files inside $(docv) too. Without it a scene reads only \
               inside the folders #include searches: the current folder, the scene's \
               folder, $(b,--include-path) folders and POV-Ray's include folder. Repeatable.")

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
    Arg.(value & opt (some int) None & info [ "spp" ] ~docv:"N"
           ~doc:"Samples per pixel in $(b,mc) mode (default 64; ignored, with a warning, in \
                 whitted mode).")
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
  let region =
    Arg.(value & opt (some string) None & info [ "region" ] ~docv:"X0,Y0,X1,Y1"
           ~doc:"Render only this rectangle (0-based pixel coordinates, $(b,X1) and $(b,Y1) \
                 excluded) into a PNG that records its placement, the full size and the \
                 render's identity; $(b,camlray merge) assembles such parts. POV-Ray's \
                 $(b,+SR +ER +SC +EC) are translated into it.")
  in
  let pov_region =
    Arg.(value & opt (some string) None & info [ "pov-region" ] ~docs:Manpage.s_none)
  in
  (* "A..B" *)
  let range conv =
    let parse s =
      let bad () = Error (`Msg (Printf.sprintf "expected A..B, found %S" s)) in
      match String.index_opt s '.' with
      | Some i when i + 1 < String.length s && s.[i + 1] = '.' -> (
          let a = String.sub s 0 i and b = String.sub s (i + 2) (String.length s - i - 2) in
          match (conv a, conv b) with Some a, Some b -> Ok (a, b) | _ -> bad ())
      | _ -> bad ()
    in
    Arg.conv (parse, fun ppf _ -> Format.pp_print_string ppf "A..B")
  in
  let frames =
    Arg.(value & opt (some (range int_of_string_opt)) None & info [ "frames" ] ~docv:"A..B"
           ~doc:"Render frames $(b,A) to $(b,B) of an animation (POV-Ray's $(b,+KFI +KFF)), \
                 each to its own file named as POV-Ray names them: the frame number padded \
                 to the digits of the last frame ($(b,s01.png) ... $(b,s12.png)).")
  in
  let clock =
    Arg.(value & opt (some float) None & info [ "clock" ] ~docv:"T"
           ~doc:"The value of $(b,clock) for a single frame (POV-Ray's $(b,+K)); default 0.")
  in
  let clock_range =
    Arg.(value & opt (some (range float_of_string_opt)) None & info [ "clock-range" ]
           ~docv:"C0..C1"
           ~doc:"The clock at the first and last frame (POV-Ray's $(b,+KI +KF)); default 0..1.")
  in
  let subset =
    Arg.(value & opt (some (range int_of_string_opt)) None & info [ "subset" ] ~docv:"A..B"
           ~doc:"Render only frames $(b,A) to $(b,B) of the animation given by $(b,--frames) \
                 (POV-Ray's $(b,+SF +EF)): the clock and file names are those of the whole \
                 animation, so frames can be shared out between machines.")
  in
  let tile_order_seed =
    Arg.(value & opt (some int) None & info [ "tile-order-seed" ] ~docs:Manpage.s_none)
  in
  let run scene output width height mode spp depth domains seed quiet include_dirs allow_read
      region pov_region frames clock clock_range subset tile_order_seed (aa, aa_depth) limits =
    Driver.render
      { Driver.scene; output; width; height; mode; spp; depth; domains; seed; quiet; include_dirs;
        allow_read; region; pov_region; frames; clock; clock_range; subset; tile_order_seed; aa;
        aa_depth; limits }
  in
  let term =
    Term.(const run $ scene_arg $ output $ width $ height $ mode $ spp $ depth $ domains $ seed
          $ quiet $ include_path $ allow_read $ region $ pov_region $ frames $ clock $ clock_range
          $ subset $ tile_order_seed $ aa_args $ limits)
  in
  let man =
    [ `S Manpage.s_description;
      `P "Renders a scene written in POV-Ray 3.7's scene description language (the subset \
          camlray supports) to an image.";
      `S Manpage.s_examples;
      `Pre "  camlray render scenes/default.scn -W 320 -H 240 -o small.png\n\
           \  camlray render scene.scn --mode mc --spp 256 -o scene-mc.png";
      `S "POV-RAY SWITCHES";
      `P "POV-Ray's switches and INI files work as they do in POV-Ray, translated into the \
          options above: $(b,camlray render scene.pov +W800 +H600 +A0.3 +Oout.png), \
          $(b,camlray render scene.ini) or $(b,camlray render scene.pov settings.ini). \
          Unknown INI keys are warned about by name.";
      `Blocks (List.map (fun (sw, what) -> `I (sw, what)) Povargs.switches);
      `S Manpage.s_exit_status;
      `P "0 on success; 1 for an error in the scene, a file or a value; 2 for misuse of the \
          command line; 130 when interrupted." ]
  in
  Cmd.v (Cmd.info "render" ~doc:"Render a scene to an image." ~man) term

let check_cmd =
  let scene = Arg.(required & pos 0 (some string) None & info [] ~docv:"SCENE" ~doc:"The scene file.") in
  let frame =
    Arg.(value & opt int 0 & info [ "frame" ] ~docv:"N"
           ~doc:"Read the scene as frame $(docv) of an animation ($(b,frame_number)).")
  in
  let clock =
    Arg.(value & opt float 0. & info [ "clock" ] ~docv:"T" ~doc:"The value of $(b,clock).")
  in
  Cmd.v
    (Cmd.info "check" ~doc:"Parse and compile a scene, report errors, render nothing.")
    Term.(const Driver.check $ scene $ include_path $ allow_read $ limits $ frame $ clock)

let merge_cmd =
  let parts = Arg.(non_empty & pos_all file [] & info [] ~docv:"PART" ~doc:"Partial renders (PNG).") in
  let out =
    Arg.(required & opt (some string) None & info [ "o"; "output" ] ~docv:"OUT" ~doc:"The full image.")
  in
  Cmd.v
    (Cmd.info "merge"
       ~doc:"Assemble partial renders ($(b,render --region)) into the full image; refuses parts \
             of different renders, gaps and overlaps.")
    Term.(const Driver.merge $ parts $ out)

let scenes_cmd =
  let run () =
    let w = List.fold_left (fun m (p, _) -> max m (String.length p)) 0 Scene_list.all in
    List.iter (fun (p, d) -> Printf.printf "%-*s  %s\n" w p d) Scene_list.all;
    0
  in
  Cmd.v
    (Cmd.info "scenes" ~doc:"List the scenes that come with camlray, a line each.")
    Term.(const run $ const ())

let obj2pov_cmd =
  let file = Arg.(required & pos 0 (some file) None & info [] ~docv:"FILE.obj" ~doc:"A Wavefront OBJ file.") in
  Cmd.v
    (Cmd.info "obj2pov"
       ~doc:"Convert a Wavefront OBJ file into POV-Ray mesh2 declarations (on standard output)."
       ~man:[ `S Manpage.s_description;
              `P "Writes one $(b,#declare OBJ_<group> = mesh2 {...}) per group or object, \
                  polygons triangulated, then $(b,OBJ_<file>_all) gathering them. Both camlray \
                  and POV-Ray read the result." ])
    Term.(const Obj2pov.run $ file)

let main =
  let man =
    [ `S Manpage.s_description;
      `P "camlray is a multicore ray tracer for scenes written in POV-Ray 3.7's scene \
          description language.";
      `S Manpage.s_examples;
      `Pre "  camlray render scenes/default.scn -o out.png\n  camlray check scene.scn" ]
  in
  Cmd.group (Cmd.info "camlray" ~version:"0.1.0" ~doc:"multicore ray tracer for POV-Ray scenes" ~man)
    [ render_cmd; check_cmd; merge_cmd; scenes_cmd; obj2pov_cmd; Compare.cmd ~aa_args ~include_path ]

let () =
  (* before any scene exists: see Scratch *)
  Camlray.Scratch.set_apart ();
  let err_buf = Buffer.create 256 in
  let err = Format.formatter_of_buffer err_buf in
  let argv =
    match Array.to_list Sys.argv with
    | prog :: "render" :: rest -> (
        match Povargs.rewrite ~warn:(fun w -> prerr_endline ("camlray: warning: " ^ w)) rest with
        | Ok args -> Array.of_list (prog :: "render" :: args)
        | Error (Povargs.Misuse m) ->
            prerr_endline ("camlray: " ^ m ^ " (see 'camlray render --help')");
            exit exit_misuse
        | Error (Povargs.Bad_file m) ->
            prerr_endline ("camlray: " ^ m);
            exit 1)
    | l -> Array.of_list l
  in
  (* an exception escaping is a bug in camlray, never the scene's fault:
     say which, on one line, with cmdliner's internal-error status *)
  match Cmd.eval_value ~catch:false ~argv ~err main with
  | exception e ->
      prerr_endline
        ("camlray: internal error: " ^ Printexc.to_string e
         ^ " (a bug in camlray, not in the scene: please report it with the scene)");
      exit Cmd.Exit.internal_error
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
