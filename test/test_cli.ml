(* The real executable: exit codes and messages. *)
let contains = Helpers.contains

let with_scene text f =
  let d = Helpers.temp_dir () in
  let p = Filename.concat d "s.scn" in
  Helpers.write_file p text;
  f d p

let units =
  [
    Alcotest.test_case "a syntax error is located, quoted with a caret, exit 1" `Quick (fun () ->
        with_scene "#version 3.7;\nsphere { <0,0,0>, 1\n  pigment { rgb 1 }\nlight_source { <0,5,0> }\n"
          (fun d p ->
            let code, _, err = Helpers.run [ "render"; p; "-W"; "8"; "-H"; "8"; "-o"; Filename.concat d "o.png" ] in
            Alcotest.(check int) "exit" 1 code;
            Alcotest.(check bool) ("located: " ^ err) true (contains err (p ^ ":4:1: error:"));
            Alcotest.(check bool) "caret" true (contains err "\n  ^");
            Alcotest.(check bool) "no exception" false (contains err "Fatal error");
            Alcotest.(check bool) "no image" false (Sys.file_exists (Filename.concat d "o.png"))));
    Alcotest.test_case "check reports the same error" `Quick (fun () ->
        with_scene "sphere { <0,0,0> 1 pigment { rgb <1,0 } }" (fun _ p ->
            let code, _, err = Helpers.run [ "check"; p ] in
            Alcotest.(check int) "exit" 1 code;
            Alcotest.(check bool) err true (contains err (p ^ ":1:"))));
    Alcotest.test_case "check accepts a good scene" `Quick (fun () ->
        with_scene "sphere { 0, 1 }\nlight_source { <1,1,1> color rgb 1 }" (fun _ p ->
            let code, out, _ = Helpers.run [ "check"; p ] in
            Alcotest.(check int) "exit" 0 code;
            Alcotest.(check bool) out true (contains out "1 objects, 1 lights")));
    Alcotest.test_case "check reads a frame of an animation (--frame, --clock)" `Quick (fun () ->
        with_scene "#if (frame_number != 3 | clock != 0.5) #error \"not frame 3\" #end\nsphere { 0, 1 }"
          (fun _ p ->
            let code, _, err = Helpers.run [ "check"; p ] in
            Alcotest.(check int) ("frame 0: " ^ err) 1 code;
            let code, _, err = Helpers.run [ "check"; p; "--frame"; "3"; "--clock"; "0.5" ] in
            Alcotest.(check int) ("frame 3: " ^ err) 0 code));
    Alcotest.test_case "a missing scene file: one line, exit 1" `Quick (fun () ->
        let code, _, err = Helpers.run [ "render"; "/nonexistent/x.scn" ] in
        Alcotest.(check int) "exit" 1 code;
        Alcotest.(check bool) err true (contains err "cannot read scene /nonexistent/x.scn");
        Alcotest.(check int) "one line" 1 (List.length (String.split_on_char '\n' (String.trim err))));
    Alcotest.test_case "-W 0 is refused by name, exit 1" `Quick (fun () ->
        let code, _, err = Helpers.run [ "render"; "-W"; "0" ] in
        Alcotest.(check int) "exit" 1 code;
        Alcotest.(check bool) err true (contains err "width"));
    Alcotest.test_case "an unknown option is misuse: exit 2, one line" `Quick (fun () ->
        let code, _, err = Helpers.run [ "render"; "--bogus" ] in
        Alcotest.(check int) "exit" 2 code;
        Alcotest.(check bool) err true (contains err "camlray:");
        Alcotest.(check int) "one line" 1 (List.length (String.split_on_char '\n' (String.trim err))));
    Alcotest.test_case "render writes a PNG of the requested size" `Quick (fun () ->
        let d = Helpers.temp_dir () in
        let out = Filename.concat d "x.png" in
        let code, _, err = Helpers.run [ "render"; "-W"; "20"; "-H"; "10"; "-o"; out ] in
        Alcotest.(check int) ("exit: " ^ err) 0 code;
        let img = Camlray.Image.read out in
        Alcotest.(check (pair int int)) "size" (20, 10) (img.w, img.h));
    Alcotest.test_case "default output name is the scene's base name" `Quick (fun () ->
        with_scene "sphere { 0, 1 }" (fun d p ->
            let code, _, _ =
              Helpers.run [ "render"; p; "-W"; "4"; "-H"; "4"; "-o"; Filename.concat d "s.png" ]
            in
            Alcotest.(check int) "exit" 0 code;
            Alcotest.(check bool) "exists" true (Sys.file_exists (Filename.concat d "s.png"))));
    Alcotest.test_case "an unwritable output folder: exit 1, nothing written" `Quick (fun () ->
        let code, _, err = Helpers.run [ "render"; "-W"; "4"; "-H"; "4"; "-o"; "/nonexistent/dir/x.png" ] in
        Alcotest.(check int) "exit" 1 code;
        Alcotest.(check bool) err true (contains err "/nonexistent/dir"));
    Alcotest.test_case "the output may not be the scene itself" `Quick (fun () ->
        with_scene "sphere { 0, 1 }" (fun _ p ->
            let before = In_channel.with_open_bin p In_channel.input_all in
            let code, _, _ = Helpers.run [ "render"; p; "-W"; "4"; "-H"; "4"; "-o"; p ] in
            Alcotest.(check int) "exit" 1 code;
            Alcotest.(check string) "untouched" before (In_channel.with_open_bin p In_channel.input_all)));
    Alcotest.test_case "more domains than cores: a warning, none with -q or within the count" `Quick (fun () ->
        with_scene "sphere { 0, 1 }" (fun d p ->
            let cores = Domain.recommended_domain_count () in
            let render extra j =
              Helpers.run
                ([ "render"; p; "-W"; "4"; "-H"; "4"; "-j"; string_of_int j; "-o"; Filename.concat d "o.png" ] @ extra)
            in
            let code, _, err = render [] (cores + 1) in
            Alcotest.(check int) "exit" 0 code;
            Alcotest.(check bool) err true
              (contains err (Printf.sprintf "warning: %d domains on %d cores" (cores + 1) cores));
            let _, _, err = render [ "-q" ] (cores + 1) in
            Alcotest.(check bool) ("quiet: " ^ err) false (contains err "warning");
            let _, _, err = render [] cores in
            Alcotest.(check bool) ("within: " ^ err) false (contains err "warning")));
    Alcotest.test_case "--help is a man page" `Quick (fun () ->
        let code, out, _ = Helpers.run [ "render"; "--help=plain" ] in
        Alcotest.(check int) "exit" 0 code;
        Alcotest.(check bool) "examples" true (contains out "EXAMPLES");
        Alcotest.(check bool) "spp" true (contains out "--spp"));
  ]

let tests = ("cli", units)
