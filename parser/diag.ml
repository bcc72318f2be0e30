type t = { loc : Loc.t; msg : string; chain : (string * Loc.t) list }

exception Error of t

let sources : (string, string) Hashtbl.t = Hashtbl.create 8
let sources_lock = Mutex.create ()

let register_source file text =
  Mutex.protect sources_lock (fun () -> Hashtbl.replace sources file text)

let source_line file n =
  match Mutex.protect sources_lock (fun () -> Hashtbl.find_opt sources file) with
  | None -> None
  | Some text ->
      let lines = String.split_on_char '\n' text in
      List.nth_opt lines (n - 1)

let quote (loc : Loc.t) =
  match source_line loc.file (Loc.line loc) with
  | None -> ""
  | Some l ->
      let l = String.map (fun c -> if c = '\t' then ' ' else c) l in
      let col = max 1 (Loc.col loc) in
      let width =
        if loc.stop.pos_lnum = loc.start.pos_lnum then
          max 1 (loc.stop.pos_cnum - loc.start.pos_cnum)
        else 1
      in
      let width = max 1 (min width (String.length l - col + 1)) in
      Printf.sprintf "  %s\n  %s%s\n" l (String.make (col - 1) ' ') (String.make width '^')

let report kind (loc : Loc.t) msg =
  if loc == Loc.none then Printf.sprintf "camlray: %s: %s\n" kind msg
  else Printf.sprintf "%s: %s: %s\n%s" (Loc.to_string loc) kind msg (quote loc)

let to_string d =
  report "error" d.loc d.msg
  ^ String.concat ""
      (List.map (fun (what, l) -> Printf.sprintf "  %s %s\n" what (Loc.to_string l)) d.chain)

let error ?(chain = []) loc fmt =
  Printf.ksprintf (fun msg -> raise (Error { loc; msg; chain })) fmt

let warnings = Atomic.make prerr_string
let warning loc msg = (Atomic.get warnings) (report "warning" loc msg)

let collect_warnings f =
  let got = Buffer.create 64 in
  let before = Atomic.exchange warnings (Buffer.add_string got) in
  Fun.protect ~finally:(fun () -> Atomic.set warnings before) (fun () ->
      let r = f () in
      (r, Buffer.contents got))
