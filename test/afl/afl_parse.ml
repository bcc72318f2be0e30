(* One AFL++ input: parse and compile the file with small limits. A located
   error is a normal outcome; an escaped exception, an internal error or a
   parse still running after 2 s aborts, which AFL records as a crash.
   [afl_parse --dict] prints the language's keywords as an AFL dictionary. *)
let () =
  if Sys.argv.(1) = "--dict" then
    List.iter (fun k -> Printf.printf "kw_%s=\"%s\"\n" k k) (Camlray_lang.Lexer.keyword_names ())
  else
    let text = In_channel.with_open_bin Sys.argv.(1) In_channel.input_all in
    match Fuzz_gen.with_stderr_silenced (fun () -> Fuzz_gen.check ~timeout:2 text) with
    | Fuzz_gen.Accepted | Fuzz_gen.Rejected -> exit 0
    | Fuzz_gen.Crashed m ->
        prerr_endline ("crash: " ^ m);
        Unix.kill (Unix.getpid ()) Sys.sigabrt
    | Fuzz_gen.Hung ->
        prerr_endline "hang";
        Unix.kill (Unix.getpid ()) Sys.sigabrt
