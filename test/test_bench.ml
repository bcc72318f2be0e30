(* The benchmarks must not rot: a seconds-long smoke run of each
   (measurements are taken with make bench, never asserted). *)
let whole =
  Alcotest.test_case "whole-render benchmark runs (--quick) and writes its tables" `Slow (fun () ->
      let bench = Filename.concat (Sys.getcwd ()) "../bench/whole/whole.exe" in
      if not (Sys.file_exists bench) then Alcotest.failf "not built: %s" bench;
      let d = Helpers.temp_dir () in
      let root = Filename.dirname (Helpers.scenes_dir ()) in
      let cmd =
        Printf.sprintf "cd %s && %s --quick --exe %s --out %s --svg %s >/dev/null 2>&1" (Filename.quote root)
          (Filename.quote bench) (Filename.quote (Helpers.exe ())) (Filename.quote d)
          (Filename.quote (Filename.concat d "s.svg"))
      in
      Alcotest.(check int) "exit" 0 (Sys.command cmd);
      let table = In_channel.with_open_bin (Filename.concat d "scaling.md") In_channel.input_all in
      Alcotest.(check bool) "has rows" true (Helpers.contains table "| default (whitted) | 1 |");
      (* the 2-domain row carries the machine's ceiling, measured *)
      let row =
        List.find (fun l -> Helpers.contains l "| default (whitted) | 2 |") (String.split_on_char '\n' table)
      in
      let cells = List.map String.trim (String.split_on_char '|' row) in
      Alcotest.(check int) "cells" 15 (List.length cells);
      (List.iter
        (fun (k, what) ->
          match Scanf.sscanf_opt (List.nth cells k) "%fx%!" Fun.id with
          | Some c when c > 0. -> ()
          | _ -> Alcotest.failf "%s cell %S" what (List.nth cells k))
        [ (5, "paired speed-up"); (11, "ceiling") ]);
      (* with povray installed, the harness scenes' table too *)
      if Sys.command "command -v povray >/dev/null 2>&1" = 0 then begin
        let h = In_channel.with_open_bin (Filename.concat d "harness.md") In_channel.input_all in
        if not (Helpers.contains h "| default |" && Helpers.contains h "one thread, no anti-aliasing: trace ratio") then
          Alcotest.failf "harness table: %S" h
      end)

let objects =
  Alcotest.test_case "object-count benchmark smoke run" `Quick (fun () ->
      let rows = Camlray_bench.Bench.run ~sizes:[ 10; 1000 ] ~width:32 ~height:24 () in
      Alcotest.(check int) "rows: 4 workloads at 2 sizes" 8 (List.length rows);
      Alcotest.(check (list string)) "workloads"
        [ "sphere mesh"; "sphere shell"; "spheres"; "terrain mesh" ]
        (List.sort_uniq compare (List.map (fun (r : Camlray_bench.Bench.row) -> r.kind) rows));
      List.iter
        (fun (r : Camlray_bench.Bench.row) ->
          if not (Float.is_finite r.trace_s && r.count > 0) then Alcotest.failf "bad row %s" r.kind)
        rows)

let tests = ("bench", [ whole; objects ])
