(* Golden tests: every test/golden/NAME.scn is checked with the real
   executable ([camlray check NAME.scn --include-path inc], run in
   test/golden) and its stderr must equal NAME.expected; the exit code
   must be 1 when the expected text holds an error, else 0. Set
   CAMLRAY_PROMOTE=1 (or CAMLRAY_UPDATE_GOLDEN=1, as for test/errors) to
   rewrite the .expected files from the actual output (then review the
   diff). test/errors checks Parse's reports in-process; these cases
   check the whole command, warnings and #debug output included. *)

let exe () =
  match Sys.getenv_opt "CAMLRAY_EXE" with
  | Some e -> e
  | None -> Filename.concat (Sys.getcwd ()) "../install/default/bin/camlray"

let dir =
  (* the source folder (cwd is _build/default/test) *)
  if Sys.file_exists "../../../test/golden" then "../../../test/golden" else "golden"

let read path = In_channel.with_open_bin path In_channel.input_all

let run name =
  let err = Filename.temp_file "golden" ".err" in
  let cmd =
    Printf.sprintf
      "cd %s && %s check %s --include-path inc --max-loop 1000 --max-macro-depth 50 \
       --max-objects 5000 --max-array 100000 >/dev/null 2>%s"
      (Filename.quote dir) (Filename.quote (exe ())) (Filename.quote (name ^ ".scn"))
      (Filename.quote err)
  in
  let code = Sys.command cmd in
  let out = read err in
  Sys.remove err;
  (code, out)

let contains s sub =
  let n = String.length sub in
  let rec go i = i + n <= String.length s && (String.sub s i n = sub || go (i + 1)) in
  go 0

let case name =
  Alcotest.test_case name `Quick (fun () ->
      let code, actual = run name in
      let exp_file = Filename.concat dir (name ^ ".expected") in
      let promote v = Sys.getenv_opt v = Some "1" in
      if promote "CAMLRAY_PROMOTE" || promote "CAMLRAY_UPDATE_GOLDEN" then begin
        Out_channel.with_open_bin exp_file (fun oc -> output_string oc actual)
      end;
      let expected = if Sys.file_exists exp_file then read exp_file else "<missing .expected>" in
      Alcotest.(check string) (name ^ ": stderr") expected actual;
      let want = if contains expected ": error: " then 1 else 0 in
      Alcotest.(check int) (name ^ ": exit code") want code)

let names () =
  if not (Sys.file_exists dir) then []
  else
    Sys.readdir dir |> Array.to_list
    |> List.filter (fun f -> Filename.check_suffix f ".scn")
    |> List.map Filename.remove_extension
    |> List.sort compare

let tests = ("golden", List.map case (names ()))
