(* Shared test helpers: scenes from strings, the real executable. *)
open Camlray
open Camlray_lang

let compile_string ?(name = "test.scn") text =
  match Parse.string ~name text with
  | Error d -> Alcotest.failf "parse error: %s" (Diag.to_string d)
  | Ok sdl -> (
      match Compile.scene sdl with
      | Error d -> Alcotest.failf "compile error: %s" (Diag.to_string d)
      | Ok s -> s)

(* Render a scene string in whitted mode, returning the linear image. *)
let render_whitted ?(domains = 1) ~width ~height text =
  let s = compile_string text in
  Render.image ~domains ~width ~height (Whitted.pixel s ~width ~height)

let pixel img x y = (Image.get_r img x y, Image.get_g img x y, Image.get_b img x y)

let exe () =
  match Sys.getenv_opt "CAMLRAY_EXE" with
  | Some e -> e
  | None -> Filename.concat (Sys.getcwd ()) "../install/default/bin/camlray"

(* Run the executable; returns (exit code, stdout, stderr). *)
let run args =
  let out = Filename.temp_file "camlray" ".out" and err = Filename.temp_file "camlray" ".err" in
  let cmd =
    Printf.sprintf "%s %s >%s 2>%s </dev/null" (Filename.quote (exe ()))
      (String.concat " " (List.map Filename.quote args)) out err
  in
  let code = Sys.command cmd in
  let read f = In_channel.with_open_bin f In_channel.input_all in
  let o = read out and e = read err in
  Sys.remove out;
  Sys.remove err;
  (code, o, e)

(* A path and what is under it removed (a symbolic link itself, not
   what it points to) *)
let rec remove_tree p =
  match (Unix.lstat p).st_kind with
  | Unix.S_DIR ->
      Array.iter (fun e -> remove_tree (Filename.concat p e)) (Sys.readdir p);
      Unix.rmdir p
  | _ -> Sys.remove p
  | exception Unix.Unix_error (Unix.ENOENT, _, _) -> ()

(* The folders [temp_dir] made, removed with their contents when the
   test program ends, but for those a failure message points to *)
let made = ref []
let () = at_exit (fun () -> List.iter (fun d -> try remove_tree d with Sys_error _ | Unix.Unix_error _ -> ()) !made)

let temp_dir ?(prefix = "camlray") () =
  let d = Filename.temp_dir prefix ".d" in
  made := d :: !made;
  d

(* [d] left in place for whoever reads the failure that names it *)
let keep d = made := List.filter (fun e -> e <> d) !made

let write_file path text = Out_channel.with_open_bin path (fun oc -> output_string oc text)

let contains s sub =
  let n = String.length s and m = String.length sub in
  let rec go i = i + m <= n && (String.sub s i m = sub || go (i + 1)) in
  go 0

let close ?(eps = 1e-9) a b = Float.abs (a -. b) <= eps

(* The source scenes/ folder. *)
let scenes_dir () =
  match Sys.getenv_opt "CAMLRAY_SCENES" with Some d -> d | None -> "../scenes"

(* A folder of test data in the source tree's test/ (from the test's
   build folder, or beside it) *)
let data_dir name = if Sys.file_exists ("../../../test/" ^ name) then "../../../test/" ^ name else name

(* The rows of numbers of a text file written by POV-Ray (#write of
   values separated by spaces), each a list of floats *)
let read_rows dir name =
  let ic = open_in (Filename.concat dir name) in
  let rec go acc =
    match input_line ic with
    | l -> go (List.map float_of_string (String.split_on_char ' ' (String.trim l)) :: acc)
    | exception End_of_file ->
        close_in ic;
        List.rev acc
  in
  go []
