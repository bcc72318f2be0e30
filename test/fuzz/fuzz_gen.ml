open Camlray_lang

let read path = try Some (In_channel.with_open_bin path In_channel.input_all) with Sys_error _ -> None

let rec find_root dir n =
  if n = 0 then None
  else if Sys.file_exists (Filename.concat dir "dune-project") && Sys.file_exists (Filename.concat dir "scenes")
  then Some dir
  else find_root (Filename.dirname dir) (n - 1)

let files_in dir ext =
  if Sys.file_exists dir && Sys.is_directory dir then
    Sys.readdir dir |> Array.to_list |> List.sort compare
    |> List.filter (fun f -> Filename.check_suffix f ext)
    |> List.map (Filename.concat dir)
  else []

let pov_examples =
  [ "advanced/woodbox.pov"; "advanced/chess2.pov"; "advanced/glasschess/glasschess.pov";
    "incdemo/colors.pov"; "portfolio/t_metals.pov"; "portfolio/f_finish.pov";
    "templates/Basic_Scenes/DarkBlueSky_Axes.pov"; "language/trace.pov" ]
  @ List.map (fun f -> "language/arrays/" ^ f) (Array.to_list (try Sys.readdir "/usr/share/doc/povray/examples/language/arrays" with Sys_error _ -> [||]))
  @ List.map (fun f -> "language/macros/" ^ f) (Array.to_list (try Sys.readdir "/usr/share/doc/povray/examples/language/macros" with Sys_error _ -> [||]))

let corpus () =
  let root =
    (* the test runs in _build/default/test; prefer the source tree *)
    match find_root (Sys.getcwd ()) 6 with
    | Some r when Filename.basename (Filename.dirname r) = "_build" ->
        Filename.dirname (Filename.dirname r)
    | Some r -> r
    | None -> "."
  in
  let root = if Sys.file_exists (Filename.concat root "_build") then root else root in
  let mine =
    files_in (Filename.concat root "scenes") ".scn"
    @ files_in (Filename.concat root "test/golden") ".scn"
  in
  let pov = List.map (Filename.concat "/usr/share/doc/povray/examples") pov_examples in
  List.filter_map (fun f -> Option.map (fun t -> (f, t)) (read f)) (mine @ pov)

let words =
  lazy
    (Array.of_list
       (Lexer.keyword_names ()
       @ [ "{"; "}"; "("; ")"; "["; "]"; "<"; ">"; "<="; ">="; "="; "!="; "+"; "-"; "*"; "/";
           ","; ";"; "?"; ":"; "&"; "|"; "!"; ".x"; ".red"; ".gray"; "0"; "1"; "2.5"; "-1";
           "1e300"; "1e-300"; ".5"; "1."; "0.0"; "A"; "B"; "Foo"; "clock"; "image_width";
           "\"s\""; "\"colors.inc\""; "#declare"; "#local"; "#undef"; "#if"; "#ifdef";
           "#ifndef"; "#else"; "#elseif"; "#end"; "#while"; "#for"; "#switch"; "#case";
           "#range"; "#break"; "#macro"; "#version"; "#default"; "#include"; "#debug";
           "#warning"; "#error"; "array"; "marble"; "box"; "normal"; "dimension_size";
           "defined"; "seed"; "rand"; "/*"; "*/"; "//"; "\n"; "@" ]))

let token_soup st =
  let w = Lazy.force words in
  let n = 1 + Random.State.int st 60 in
  String.concat " " (List.init n (fun _ -> w.(Random.State.int st (Array.length w))))

let mutate_once st s =
  let len = String.length s in
  if len = 0 then token_soup st
  else
    let a = Random.State.int st len in
    let b = min len (a + 1 + Random.State.int st 40) in
    let w = Lazy.force words in
    match Random.State.int st 6 with
    | 0 -> String.sub s 0 a ^ String.sub s b (len - b)
    | 1 -> String.sub s 0 b ^ String.sub s a (b - a) ^ String.sub s b (len - b)
    | 2 -> String.sub s 0 a ^ " " ^ w.(Random.State.int st (Array.length w)) ^ " " ^ String.sub s a (len - a)
    | 3 ->
        let c = Bytes.of_string s in
        Bytes.set c a (Char.chr (32 + Random.State.int st 95));
        Bytes.to_string c
    | 4 -> String.sub s 0 a
    | _ ->
        let c = Random.State.int st len in
        let piece = String.sub s a (b - a) in
        let rest = String.sub s 0 a ^ String.sub s b (len - b) in
        let c = min c (String.length rest) in
        String.sub rest 0 c ^ piece ^ String.sub rest c (String.length rest - c)

let mutate st s =
  let k = 1 + Random.State.int st 4 in
  let rec go s k = if k = 0 then s else go (mutate_once st s) (k - 1) in
  go s k

let input st corpus =
  if corpus = [] || Random.State.bool st then token_soup st
  else
    let _, text = List.nth corpus (Random.State.int st (List.length corpus)) in
    mutate st text

type outcome = Accepted | Rejected | Crashed of string | Hung

exception Timeout

let options =
  {
    Parse.default_options with
    limits =
      { Supplier.default_limits with max_loop_iterations = 200; max_macro_depth = 30;
        max_array_size = 100_000; max_tokens = 200_000 };
  }

let check ?timeout text =
  let run () =
    match Parse.string ~options ~name:"fuzz.pov" text with
    | Ok sdl -> ( match Compile.scene sdl with Ok _ | Error _ -> Accepted)
    | Error d when String.length d.msg >= 14 && String.sub d.msg 0 14 = "internal error" ->
        Crashed d.msg
    | Error _ -> Rejected
    | exception Timeout -> Hung
    | exception e -> Crashed (Printexc.to_string e)
  in
  match timeout with
  | None -> run ()
  | Some s ->
      let old = Sys.signal Sys.sigalrm (Sys.Signal_handle (fun _ -> raise Timeout)) in
      ignore (Unix.alarm s);
      Fun.protect run ~finally:(fun () ->
          ignore (Unix.alarm 0);
          Sys.set_signal Sys.sigalrm old)

let with_stderr_silenced f =
  flush stderr;
  let saved = Unix.dup Unix.stderr in
  let null = Unix.openfile "/dev/null" [ Unix.O_WRONLY ] 0 in
  Unix.dup2 null Unix.stderr;
  Unix.close null;
  Fun.protect f ~finally:(fun () ->
      flush stderr;
      Unix.dup2 saved Unix.stderr;
      Unix.close saved)
