(* A scene reads only inside the include search folders unless
   --allow-read grants more. *)
let contains = Helpers.contains

let setup () =
  let root = Helpers.temp_dir () in
  let scenes = Filename.concat root "scenes" and secret = Filename.concat root "secret" in
  Sys.mkdir scenes 0o755;
  Sys.mkdir secret 0o755;
  Helpers.write_file (Filename.concat secret "s.inc") "#declare R = 1;\n";
  Helpers.write_file (Filename.concat scenes "ok.inc") "#declare R = 1;\n";
  (root, scenes, secret)

let scene dir name text =
  let p = Filename.concat dir name in
  Helpers.write_file p (text ^ "\nsphere { 0, R }\n");
  p

let refused what args =
  let code, _, err = Helpers.run args in
  Alcotest.(check int) (what ^ ": exit") 1 code;
  Alcotest.(check bool) (what ^ ": " ^ err) true (contains err "is not allowed");
  Alcotest.(check bool) (what ^ ": located") true (contains err ".scn:1:")

let units =
  [
    Alcotest.test_case "an include in the scene's folder is read" `Quick (fun () ->
        let _, scenes, _ = setup () in
        let s = scene scenes "a.scn" "#include \"ok.inc\"" in
        let code, _, err = Helpers.run [ "check"; s ] in
        Alcotest.(check int) err 0 code);
    Alcotest.test_case "absolute paths and ../ escapes are refused" `Quick (fun () ->
        let _, scenes, secret = setup () in
        refused "absolute"
          [ "check"; scene scenes "b.scn" (Printf.sprintf "#include %S" (Filename.concat secret "s.inc")) ];
        refused "dotdot" [ "check"; scene scenes "c.scn" "#include \"../secret/s.inc\"" ]);
    Alcotest.test_case "a symbolic link out of the folder is refused" `Quick (fun () ->
        let _, scenes, secret = setup () in
        Unix.symlink (Filename.concat secret "s.inc") (Filename.concat scenes "link.inc");
        refused "symlink" [ "check"; scene scenes "d.scn" "#include \"link.inc\"" ]);
    Alcotest.test_case "--allow-read grants a folder" `Quick (fun () ->
        let _, scenes, secret = setup () in
        let s = scene scenes "e.scn" "#include \"../secret/s.inc\"" in
        let code, _, err = Helpers.run [ "check"; s; "--allow-read"; secret ] in
        Alcotest.(check int) err 0 code);
  ]

let tests = ("access", units)
