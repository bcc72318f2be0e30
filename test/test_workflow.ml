(* POV-Ray habits (switches, INI files), animation frames, partial
   renders and their merge: through the real executable. *)
let run = Helpers.run
let contains = Helpers.contains
let scene () = Filename.concat (Helpers.scenes_dir ()) "default.scn"
let read_bytes f = In_channel.with_open_bin f In_channel.input_all

let ok what (code, _, err) = if code <> 0 then Alcotest.failf "%s: exit %d: %s" what code err

let units =
  [
    Alcotest.test_case "POV-Ray switches +W +H +O" `Quick (fun () ->
        let d = Helpers.temp_dir () in
        let out = Filename.concat d "o.png" in
        ok "render" (run [ "render"; scene (); "+W20"; "+H10"; "+O" ^ out; "-D"; "-q" ]);
        let img = Camlray.Image.read out in
        Alcotest.(check (pair int int)) "size" (20, 10) (img.w, img.h));
    Alcotest.test_case "an unknown POV-Ray switch is misuse (exit 2)" `Quick (fun () ->
        let code, _, err = run [ "render"; "+Z3" ] in
        Alcotest.(check int) "exit" 2 code;
        Alcotest.(check bool) err true (contains err "+Z3"));
    Alcotest.test_case "INI file: keys honoured, unknown keys warned by name" `Quick (fun () ->
        let d = Helpers.temp_dir () in
        let out = Filename.concat d "i.png" and ini = Filename.concat d "r.ini" in
        Helpers.write_file ini
          (Printf.sprintf "; settings\n[render]\nInput_File_Name=%s\nWidth=12\nHeight=8\nFrobnicate=on\nOutput_File_Name=%s\n"
             (scene ()) out);
        let code, _, err = run [ "render"; ini; "-q" ] in
        Alcotest.(check int) ("exit: " ^ err) 0 code;
        Alcotest.(check bool) err true (contains err "unknown INI key Frobnicate");
        let img = Camlray.Image.read out in
        Alcotest.(check (pair int int)) "size" (12, 8) (img.w, img.h));
    Alcotest.test_case "a missing INI file is a file error (exit 1)" `Quick (fun () ->
        let code, _, _ = run [ "render"; "/nonexistent/x.ini" ] in
        Alcotest.(check int) "exit" 1 code);
    Alcotest.test_case "animation frames are named as POV-Ray names them" `Quick (fun () ->
        let d = Helpers.temp_dir () in
        let s = Filename.concat d "s.scn" in
        Helpers.write_file s "sphere { <clock*2-1, 0, 3>, 0.5 pigment { rgb 1 } }\nlight_source { <0,5,-5> color rgb 1 }\n";
        ok "render" (run [ "render"; s; "+W8"; "+H6"; "+KFI1"; "+KFF12"; "-o"; Filename.concat d "s.png"; "-q" ]);
        for f = 1 to 12 do
          let name = Filename.concat d (Printf.sprintf "s%02d.png" f) in
          if not (Sys.file_exists name) then Alcotest.failf "missing %s" name
        done;
        (* the clock moves the sphere: first and last frames differ *)
        Alcotest.(check bool) "moves" true
          (read_bytes (Filename.concat d "s01.png") <> read_bytes (Filename.concat d "s12.png")));
    Alcotest.test_case "a subset of frames (+SF/+EF) equals those frames of the whole animation" `Quick
      (fun () ->
        let d = Helpers.temp_dir () and e = Helpers.temp_dir () in
        let s = Filename.concat d "a.scn" in
        Helpers.write_file s "sphere { <clock*2-1, 0, 3>, 0.5 pigment { rgb 1 } }\nlight_source { <0,5,-5> color rgb 1 }\n";
        ok "all" (run [ "render"; s; "+W8"; "+H6"; "--frames"; "1..4"; "-o"; Filename.concat d "a.png"; "-q" ]);
        ok "subset" (run [ "render"; s; "+W8"; "+H6"; "+KFI1"; "+KFF4"; "+SF3"; "+EF3"; "-o"; Filename.concat e "a.png"; "-q" ]);
        Alcotest.(check (list string)) "only frame 3" [ "a3.png" ] (Array.to_list (Sys.readdir e));
        Alcotest.(check bool) "same pixels" true
          (read_bytes (Filename.concat d "a3.png") = read_bytes (Filename.concat e "a3.png")));
    Alcotest.test_case "regions merge into the whole image, byte for byte" `Quick (fun () ->
        let d = Helpers.temp_dir () in
        let f n = Filename.concat d n in
        let common = [ scene (); "-W"; "40"; "-H"; "30"; "-q" ] in
        ok "full" (run ("render" :: common @ [ "-o"; f "full.png" ]));
        ok "a" (run ("render" :: common @ [ "--region"; "0,0,40,13"; "-o"; f "a.png" ]));
        ok "b" (run ("render" :: common @ [ "--region"; "0,13,17,30"; "-o"; f "b.png" ]));
        (* POV-Ray style: rows 14..30, columns 18..40, 1-based inclusive *)
        ok "c" (run ("render" :: common @ [ "+SR14"; "+ER30"; "+SC18"; "+EC40"; "-o"; f "c.png" ]));
        ok "merge" (run [ "merge"; f "a.png"; f "b.png"; f "c.png"; "-o"; f "m.png" ]);
        Alcotest.(check bool) "identical" true (read_bytes (f "m.png") = read_bytes (f "full.png")));
    Alcotest.test_case "merge refuses gaps, overlaps and parts of other renders" `Quick (fun () ->
        let d = Helpers.temp_dir () in
        let f n = Filename.concat d n in
        let common = [ scene (); "-W"; "20"; "-H"; "10"; "-q" ] in
        ok "a" (run ("render" :: common @ [ "--region"; "0,0,20,6"; "-o"; f "a.png" ]));
        ok "b" (run ("render" :: common @ [ "--region"; "0,5,20,10"; "-o"; f "b.png" ]));
        ok "c" (run ("render" :: common @ [ "--region"; "0,6,20,10"; "--mode"; "mc"; "--spp"; "1"; "-o"; f "c.png" ]));
        let code, _, err = run [ "merge"; f "a.png"; "-o"; f "m.png" ] in
        Alcotest.(check int) "gap exit" 1 code;
        Alcotest.(check bool) err true (contains err "gap");
        let code, _, err = run [ "merge"; f "a.png"; f "b.png"; "-o"; f "m.png" ] in
        Alcotest.(check int) "overlap exit" 1 code;
        Alcotest.(check bool) err true (contains err "overlap");
        let code, _, err = run [ "merge"; f "a.png"; f "c.png"; "-o"; f "m.png" ] in
        Alcotest.(check int) "other render exit" 1 code;
        Alcotest.(check bool) err true (contains err "different renders");
        Alcotest.(check bool) "nothing written" false (Sys.file_exists (f "m.png")));
    Alcotest.test_case "a region outside the image is refused (exit 1)" `Quick (fun () ->
        let code, _, err = run [ "render"; "-W"; "20"; "-H"; "10"; "--region"; "0,0,30,10"; "-o"; "/tmp/x.png" ] in
        Alcotest.(check int) "exit" 1 code;
        Alcotest.(check bool) err true (contains err "outside"));
    Alcotest.test_case "the GNU parallel recipe gives the single render, byte for byte" `Slow (fun () ->
        if Sys.command "command -v parallel >/dev/null 2>&1" <> 0 then print_endline "GNU parallel not installed: skipped"
        else
          let d = Helpers.temp_dir () in
          let f n = Filename.concat d n in
          let exe = Filename.quote (Helpers.exe ()) and sc = Filename.quote (scene ()) in
          ok "full" (run [ "render"; scene (); "-W"; "48"; "-H"; "32"; "-q"; "-o"; f "full.png" ]);
          let cmd =
            Printf.sprintf
              "cd %s && parallel --will-cite -j2 %s render %s -W 48 -H 32 -q --domains 1 --region 0,{1},48,{2} -o part-{1}.png ::: 0 8 16 24 :::+ 8 16 24 32 && %s merge part-*.png -o merged.png"
              (Filename.quote d) exe sc exe
          in
          Alcotest.(check int) "recipe" 0 (Sys.command cmd);
          Alcotest.(check bool) "identical" true (read_bytes (f "merged.png") = read_bytes (f "full.png")));
  ]

let listing =
  [
    Alcotest.test_case "camlray scenes lists every bundled scene with a line" `Quick (fun () ->
        let code, out, _ = run [ "scenes" ] in
        Alcotest.(check int) "exit" 0 code;
        let lines = List.filter (( <> ) "") (String.split_on_char '\n' out) in
        let rec count dir =
          Array.fold_left
            (fun n f ->
              let p = Filename.concat dir f in
              if Sys.is_directory p then n + count p else if Filename.check_suffix f ".scn" then n + 1 else n)
            0 (Sys.readdir dir)
        in
        Alcotest.(check int) "one line per scene" (count (Helpers.scenes_dir ())) (List.length lines);
        Alcotest.(check bool) "default" true (contains out "scenes/default.scn"));
    Alcotest.test_case "camlray --version" `Quick (fun () ->
        let code, out, _ = run [ "--version" ] in
        Alcotest.(check int) "exit" 0 code;
        Alcotest.(check bool) out true (String.length (String.trim out) > 0));
  ]

let tests = ("workflow", units @ listing)
