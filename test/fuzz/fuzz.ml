(* make fuzz: parse N random inputs (default 100000; first argument),
   count outcomes, print every input that raised an OCaml exception. *)
let () =
  let n = if Array.length Sys.argv > 1 then int_of_string Sys.argv.(1) else 100_000 in
  let seed = if Array.length Sys.argv > 2 then int_of_string Sys.argv.(2) else 42 in
  let st = Random.State.make [| seed |] in
  let corpus = Fuzz_gen.corpus () in
  (* mutated scenes may #fopen files for writing: run in a scratch folder *)
  let scratch = Filename.temp_dir "camlray-fuzz" "" in
  Sys.chdir scratch;
  let rec remove p =
    if Sys.is_directory p then begin
      Array.iter (fun f -> remove (Filename.concat p f)) (Sys.readdir p);
      Sys.rmdir p
    end
    else Sys.remove p
  in
  at_exit (fun () -> try remove scratch with Sys_error _ -> ());
  let ok = ref 0 and rej = ref 0 and crashes = ref [] and hangs = ref [] in
  let t0 = Unix.gettimeofday () in
  Fuzz_gen.with_stderr_silenced (fun () ->
      for _ = 1 to n do
        let text = Fuzz_gen.input st corpus in
        match Fuzz_gen.check ~timeout:10 text with
        | Fuzz_gen.Hung -> hangs := text :: !hangs
        | Fuzz_gen.Accepted -> incr ok
        | Fuzz_gen.Rejected -> incr rej
        | Fuzz_gen.Crashed e -> crashes := (e, text) :: !crashes
      done);
  let dt = Unix.gettimeofday () -. t0 in
  List.iteri
    (fun i (e, text) ->
      if i < 10 then Printf.printf "CRASH %s on input:\n%s\n-----\n" e text)
    (List.rev !crashes);
  List.iteri (fun i text -> if i < 3 then Printf.printf "HANG (over 10 s) on input:\n%s\n-----\n" text) !hangs;
  Printf.printf
    "fuzz: %d inputs (corpus of %d files, seed %d) in %.1f s: %d accepted, %d rejected with a located error, %d uncaught exceptions, %d hangs\n"
    n (List.length corpus) seed dt !ok !rej (List.length !crashes) (List.length !hangs);
  exit (if !crashes = [] && !hangs = [] then 0 else 1)
