(* Interrupts, full disks, read-only folders, huge requests, scheduling:
   nothing the user had is lost, nothing crashes. *)
let contains = Helpers.contains
let scene () = Filename.concat (Helpers.scenes_dir ()) "default.scn"
let read_bytes f = In_channel.with_open_bin f In_channel.input_all

let leftovers dir =
  Sys.readdir dir |> Array.to_list |> List.filter (fun f -> Filename.check_suffix f ".tmp")

(* Start a long render, send [signal] after [after] seconds; return the
   exit status and the seconds between the signal and the exit. The
   render stops between pixels: a pixel here is some milliseconds of
   work (1,000 samples), so the stop does not wait on one long pixel
   (100,000 samples a pixel took 0.1 s on a quiet host and over 1 s on a
   loaded one) *)
let interrupt signal ~after out =
  let err = Filename.temp_file "camlray" ".err" in
  let fd = Unix.openfile err [ Unix.O_WRONLY; Unix.O_TRUNC ] 0o644 in
  let pid =
    Unix.create_process (Helpers.exe ())
      [| Helpers.exe (); "render"; scene (); "--mode"; "mc"; "--spp"; "1000"; "-W"; "640";
         "-H"; "480"; "-o"; out |]
      Unix.stdin fd fd
  in
  Unix.close fd;
  Unix.sleepf after;
  let t = Unix.gettimeofday () in
  Unix.kill pid signal;
  let _, status = Unix.waitpid [] pid in
  let dt = Unix.gettimeofday () -. t in
  let msg = read_bytes err in
  Sys.remove err;
  (status, dt, msg)

let signal_case name signal =
  Alcotest.test_case (name ^ " stops the render within a second, keeps the old image") `Quick
    (fun () ->
      let d = Helpers.temp_dir () in
      let out = Filename.concat d "keep.png" in
      Helpers.write_file out "previous image";
      let status, dt, msg = interrupt signal ~after:0.8 out in
      (match status with
      | Unix.WEXITED 130 -> ()
      | Unix.WEXITED n -> Alcotest.failf "exit %d (%s)" n msg
      | _ -> Alcotest.failf "killed by a signal (%s)" msg);
      if dt > 1.0 then Alcotest.failf "took %.2f s to stop" dt;
      Alcotest.(check string) "old image untouched" "previous image" (read_bytes out);
      Alcotest.(check (list string)) "no temporary files" [] (leftovers d))

let mounted kind f =
  let d = Helpers.temp_dir () in
  let cmd =
    match kind with
    | `Tiny -> Printf.sprintf "mount -t tmpfs -o size=16k tmpfs %s 2>/dev/null" (Filename.quote d)
    | `Ro ->
        Printf.sprintf "mount --bind %s %s 2>/dev/null && mount -o remount,bind,ro %s 2>/dev/null"
          (Filename.quote d) (Filename.quote d) (Filename.quote d)
  in
  if Sys.command cmd <> 0 then print_endline "cannot mount here (not root?): skipped"
  else
    Fun.protect
      ~finally:(fun () -> ignore (Sys.command (Printf.sprintf "umount %s" (Filename.quote d))))
      (fun () -> f d)

let units =
  [
    signal_case "SIGINT" Sys.sigint;
    signal_case "SIGTERM" Sys.sigterm;
    Alcotest.test_case "a full disk: clear error, no partial file, old image kept" `Quick (fun () ->
        mounted `Tiny (fun d ->
            let out = Filename.concat d "x.png" in
            Helpers.write_file out "old";
            let code, _, err = Helpers.run [ "render"; scene (); "-W"; "400"; "-H"; "300"; "-o"; out; "-q" ] in
            Alcotest.(check int) ("exit: " ^ err) 1 code;
            Alcotest.(check bool) err true (contains err "No space left on device");
            Alcotest.(check bool) "no exception" false (contains err "Fatal error");
            Alcotest.(check string) "old kept" "old" (read_bytes out);
            Alcotest.(check (list string)) "no temporary files" [] (leftovers d);
            (* re-running the same command after making room just works *)
            Sys.remove out;
            let code, _, err = Helpers.run [ "render"; scene (); "-W"; "40"; "-H"; "30"; "-o"; out; "-q" ] in
            Alcotest.(check int) ("rerun: " ^ err) 0 code));
    Alcotest.test_case "a read-only folder: clear error, exit 1" `Quick (fun () ->
        mounted `Ro (fun d ->
            let out = Filename.concat d "x.png" in
            let code, _, err = Helpers.run [ "render"; "-W"; "8"; "-H"; "8"; "-o"; out; "-q" ] in
            Alcotest.(check int) ("exit: " ^ err) 1 code;
            Alcotest.(check bool) err true (contains err "Read-only file system");
            Alcotest.(check bool) "nothing" false (Sys.file_exists out)));
    Alcotest.test_case "a huge image is refused before allocating, naming the number" `Quick (fun () ->
        let code, _, err = Helpers.run [ "render"; "-W"; "60000"; "-H"; "60000"; "-o"; "/tmp/never.png" ] in
        Alcotest.(check int) "exit" 1 code;
        Alcotest.(check bool) err true (contains err "3600000000"));
    Alcotest.test_case "negative or zero values are refused" `Quick (fun () ->
        List.iter
          (fun args ->
            let code, _, err = Helpers.run ("render" :: args) in
            if code <> 1 then Alcotest.failf "%s: exit %d (%s)" (String.concat " " args) code err)
          [ [ "-H"; "0" ]; [ "--spp"; "0" ]; [ "--depth"; "0" ]; [ "--domains"; "0" ]; [ "--width=-5" ] ]);
    Alcotest.test_case "random domain counts and tile orders give identical images" `Slow (fun () ->
        let d = Helpers.temp_dir () in
        let f n = Filename.concat d n in
        let render name extra =
          let code, _, err =
            Helpers.run ([ "render"; scene (); "-W"; "64"; "-H"; "48"; "-q"; "-o"; f name ] @ extra)
          in
          if code <> 0 then Alcotest.failf "render: %s" err;
          read_bytes (f name)
        in
        let st = Random.State.make [| 42 |] in
        List.iter
          (fun mode ->
            let reference = render "ref.png" ([ "--domains"; "1" ] @ mode) in
            for _ = 1 to 3 do
              let dom = 1 + Random.State.int st 8 and seed = Random.State.int st 1000 in
              let img =
                render "x.png"
                  ([ "--domains"; string_of_int dom; "--tile-order-seed"; string_of_int seed ] @ mode)
              in
              if img <> reference then Alcotest.failf "differs with %d domains, tile order %d" dom seed
            done)
          [ []; [ "--mode"; "mc"; "--spp"; "2" ] ]);
  ]

let tests = ("robustness", units)
