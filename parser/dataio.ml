(* #fopen, #write, #read, #fclose: POV-Ray's file input/output. *)
open Lexer
open Cursor

(* #fopen ID "file" read|write|append *)
let fopen t loc =
  let name, nloc = expect_ident t "a file identifier after #fopen" in
  if Hashtbl.mem t.handles name then fail t nloc "the file %s is already open" name;
  let file = Cursor.parse t Parser.Incremental.string_arg in
  let mode, mloc = expect_ident t "read, write or append" in
  match mode with
  | "read" -> (
      match find_file t file with
      | None -> fail t loc "cannot find %S to read" file
      | Some path ->
          allowed t loc path;
          let text =
            try In_channel.with_open_bin path In_channel.input_all
            with Sys_error e -> fail t loc "cannot read %s: %s" path e
          in
          Hashtbl.replace t.handles name (Reading { data = Lexer.tokenize ~file:path text; at = 0 }))
  | "write" | "append" ->
      let flags = if mode = "write" then [ Open_wronly; Open_creat; Open_trunc; Open_binary ]
        else [ Open_wronly; Open_creat; Open_append; Open_binary ] in
      allowed t loc file;
      let oc = try open_out_gen flags 0o644 file with Sys_error e -> fail t loc "cannot open %s: %s" file e in
      Hashtbl.replace t.handles name (Writing oc)
  | m -> fail t mloc "expected read, write or append, found %s" m

(* #write (ID, item, ...): strings as they are, floats as %g, vectors as
   <%g,%g,...> followed by a space (POV-Ray's format) *)
let write t loc =
  expect_tok t Parser.LPAREN "'(' after #write";
  let name, nloc = expect_ident t "a file identifier" in
  let oc = match Hashtbl.find_opt t.handles name with
    | Some (Writing oc) -> oc
    | Some (Reading _) -> fail t nloc "%s was opened for reading" name
    | None -> fail t nloc "%s is not an open file" name
  in
  (* the comma after the file identifier is optional in POV-Ray *)
  (match (raw_peek t).raw with Tok Parser.COMMA -> ignore (raw_next t) | _ -> ());
  let rec items () =
    let d, closed = Quick.macro_arg t in
    (match d with
    | Decl.Value (Value.String s) -> output_string oc s
    | Decl.Value (Value.Float f) -> Printf.fprintf oc "%g" f
    | Decl.Value (Value.Vector a) ->
        Printf.fprintf oc "<%s> " (String.concat "," (Array.to_list (Array.map (Printf.sprintf "%g") a)))
    | d -> fail t loc "#write cannot write %s" (Decl.kind_name d));
    if not closed then items ()
  in
  items ()

(* #read (ID, VAR, ...): comma-separated numbers, vectors and strings.
   At the end of the data the file closes and ID becomes undefined; the
   variables not reached stay as they were. *)
let read t loc =
  expect_tok t Parser.LPAREN "'(' after #read";
  let name, nloc = expect_ident t "a file identifier" in
  let r = match Hashtbl.find_opt t.handles name with
    | Some (Reading r) -> r
    | Some (Writing _) -> fail t nloc "%s was opened for writing" name
    | None -> fail t nloc "%s is not an open file" name
  in
  let peek () = r.data.(r.at).raw and adv () = r.at <- r.at + 1 in
  let dloc () = r.data.(r.at).loc in
  let rec skip_commas () = match peek () with Tok Parser.COMMA -> adv (); skip_commas () | _ -> () in
  let number () =
    let sign = match peek () with
      | Tok Parser.MINUS -> adv (); -1. | Tok Parser.PLUS -> adv (); 1. | _ -> 1. in
    match peek () with
    | Tok (Parser.FLOAT f) -> adv (); sign *. f
    | raw -> Diag.error (dloc ()) "expected a number in the data file, found %s" (describe raw)
  in
  let value () =
    skip_commas ();
    match peek () with
    | Eof -> None
    | Tok (Parser.STRING s) -> adv (); Some (Value.String s)
    | Tok Parser.LT ->
        adv ();
        let rec comps acc =
          let c = number () in
          match peek () with
          | Tok Parser.COMMA -> adv (); comps (c :: acc)
          | Tok Parser.GT -> adv (); List.rev (c :: acc)
          | raw -> Diag.error (dloc ()) "expected ',' or '>' in the data file, found %s" (describe raw)
        in
        Some (Value.Vector (Array.of_list (comps [])))
    | _ -> Some (Value.Float (number ()))
  in
  let rec vars () =
    (match (raw_peek t).raw with Tok Parser.COMMA -> ignore (raw_next t) | _ -> ());
    let var, _ = expect_ident t "a variable to read into" in
    (match value () with
    | Some v -> Env.declare t.env var (Env.Decl (Decl.Value v))
    | None -> Hashtbl.remove t.handles name);
    let sep = raw_next t in
    match sep.raw with
    | Tok Parser.RPAREN -> ()
    | Tok Parser.COMMA -> (top t).pos <- (top t).pos - 1; vars ()
    | raw -> fail t sep.loc "expected ',' or ')', found %s" (describe raw)
  in
  ignore loc;
  vars ();
  (* reaching the end of the data closes the file *)
  skip_commas ();
  if peek () = Eof then Hashtbl.remove t.handles name


let fclose t =
  let name, nloc = expect_ident t "a file identifier after #fclose" in
  (match Hashtbl.find_opt t.handles name with
  | Some (Writing oc) -> close_out oc
  | Some (Reading _) | None -> () (* a file that reached its end is already closed *));
  ignore nloc;
  Hashtbl.remove t.handles name

let close_files t =
  Hashtbl.iter (fun _ h -> match h with Writing oc -> close_out_noerr oc | Reading _ -> ()) t.handles;
  Hashtbl.reset t.handles

