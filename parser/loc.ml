type t = { file : string; start : Lexing.position; stop : Lexing.position }

let make (start : Lexing.position) stop = { file = start.pos_fname; start; stop }
let none = { file = "<none>"; start = Lexing.dummy_pos; stop = Lexing.dummy_pos }
let line l = l.start.pos_lnum
let col l = l.start.pos_cnum - l.start.pos_bol + 1
let to_string l = Printf.sprintf "%s:%d:%d" l.file (line l) (col l)
