(* Golden error messages: each test/errors/NAME.scn must give exactly the
   report in NAME.expected (Diag.to_string: file:line:col, message, source
   line, caret, include/macro chain). CAMLRAY_UPDATE_GOLDEN=1 rewrites the
   expected files from the current output. Files are parsed from inside
   the errors folder so that the names in the reports are short. *)
open Camlray_lang

let dir () =
  (* the test runs in _build/default/test; the sources are three levels up *)
  List.find_opt Sys.file_exists [ "errors"; "../../../test/errors"; "test/errors" ]

let in_dir d f =
  let cwd = Sys.getcwd () in
  Sys.chdir d;
  Fun.protect ~finally:(fun () -> Sys.chdir cwd) f

let report d name =
  in_dir d (fun () ->
      match Parse.file name with
      | Ok _ -> "(no error)\n"
      | Error e -> Diag.to_string e)

let case d name =
  Alcotest.test_case name `Quick (fun () ->
      let got = report d name in
      let exp = Filename.concat d (Filename.chop_suffix name ".scn" ^ ".expected") in
      if Sys.getenv_opt "CAMLRAY_UPDATE_GOLDEN" = Some "1" then
        Out_channel.with_open_bin exp (fun oc -> output_string oc got)
      else
        match In_channel.with_open_bin exp In_channel.input_all with
        | want -> Alcotest.(check string) name want got
        | exception Sys_error _ -> Alcotest.failf "missing %s; its output would be:\n%s" exp got)

let tests =
  match dir () with
  | None -> ("errors", [ Alcotest.test_case "errors folder" `Quick (fun () -> Alcotest.fail "test/errors not found") ])
  | Some d ->
      let names =
        Sys.readdir d |> Array.to_list |> List.filter (fun n -> Filename.check_suffix n ".scn")
        |> List.sort compare
      in
      ( "errors",
        Alcotest.test_case "every case has a file and the folder is not empty" `Quick (fun () ->
            Alcotest.(check bool) "cases" true (List.length names >= 20))
        :: List.map (case d) names )
