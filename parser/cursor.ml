(* The supplier's state and its raw token cursors: the stack of frames
   (file, include, macro body), open control structures, and the
   primitives every directive module uses. See cursor.mli. *)
open Lexer

type limits = {
  max_loop_iterations : int;
  max_macro_depth : int;
  max_include_depth : int;
  max_array_size : int;
  max_tokens : int;  (** raw tokens read in all, loops and macros included *)
  max_objects : int;  (** objects read or placed, see {!Budget} *)
}

let default_limits =
  { max_loop_iterations = 1_000_000; max_macro_depth = 200; max_include_depth = 64;
    max_array_size = 10_000_000; max_tokens = 1_000_000_000; max_objects = 10_000_000 }

type config = {
  include_dirs : string list;
  limits : limits;
  builtins : (string * float) list;
  access : Access.t;  (** what the scene may read and write *)
  fold : bool;
      (** fold arithmetic runs before the parser sees them ({!Fold}); the
          scene reads the same either way (off to test that) *)
  quick : bool;  (** plain expressions of directives evaluated without the parser ({!Quick}) *)
}

(* Open control structures of one frame, innermost first. *)
type ctrl =
  | In_if of Loc.t  (** executing a taken branch of #if/#ifdef/#ifndef *)
  | In_while of { cond_pos : int; mutable count : int; wloc : Loc.t }
  | In_for of {
      var : string; stop : float; step : float; body_pos : int; mutable count : int; floc : Loc.t }
  | In_switch of Loc.t  (** executing a matched clause *)

let opener = function
  | In_if l -> ("#if", l)
  | In_while w -> ("#while", w.wloc)
  | In_for r -> ("#for", r.floc)
  | In_switch l -> ("#switch", l)

(* A file opened by #fopen: data tokens to #read, or a channel to #write. *)
type reader = { data : token array; mutable at : int }
type handle = Reading of reader | Writing of out_channel

(* Where a macro parameter passed by reference writes back. *)
type target = Name of string | Element of Env.binding option array * int

type kind = Main | Include of Loc.t | Macro_call of string * Loc.t

type frame = {
  toks : Toks.t;
  mutable pos : int;
  kind : kind;
  file : string;
  mutable ctrl : ctrl list;
  scoped : bool;
  byref : (string * target) list;
      (** macro parameters given a bare identifier, with that identifier:
          their final values are copied back when the macro ends
          (POV-Ray passes identifiers by reference) *)
}

(* Runs a sub-parse from an entry point; set by Supplier.create. *)
type runner = { run : 'a. (Lexing.position -> 'a Parser.MenhirInterpreter.checkpoint) -> 'a }

type t = {
  config : config;
  builtins : float Words.t;  (** [config.builtins] as a table *)
  mutable runner : runner;
  env : Env.t;
  mutable frames : frame list;
  mutable pending : (Parser.token * Loc.t) list;  (** pushed-back tokens *)
  mutable last : Loc.t;
  mutable files : string list;
  handles : (string, handle) Hashtbl.t;  (** #fopen'ed files by identifier *)
  mutable stop_at : (frame * int) option;
      (** hand the parser a ';' when this frame reaches this position
          (ends a value that has no terminator, see {!Splread}) *)
  mutable braces : Loc.t list;  (** the '{' not yet closed, innermost first *)
  mutable skipped : string list;  (** the blocks read past ([photons]), warned once *)
  mutable context : string option;  (** what is being parsed, for messages *)
  deprecated : (string, string * bool * bool ref) Hashtbl.t;
      (** [#declare deprecated [once] "why" NAME = ...]: warn on use *)
  mutable supplied : int;  (** raw tokens read so far, for [max_tokens] *)
  mutable depth : int;  (** parses in progress: 1 while the scene's own parse reads *)
  mutable optional_sep : Parser.token option;
      (** for the next sub-parse only: a separator that may be left out
          (array initialisers: [{ <1,2> <3,4> }]); the parser gets it
          where the next token cannot continue *)
  mutable semi_probe : (string * Loc.t) option ref option;
      (** for the next sub-parse only: where a directive (or the end of
          the file) stands in the same file where a ';' could end the
          phrase, the parser is given that ';' and the directive is
          recorded here (POV-Ray: a #declare missing its ';') *)
}

let files_read t = List.rev t.files

(* The value of a built-in identifier (clock, image_width, ...), looked up
   before every name the scene uses *)
let builtin t name = Words.find_opt t.builtins name

let parse t entry = t.runner.run entry

let create config env ~file toks =
  let abs = if Filename.is_relative file then Filename.concat (Sys.getcwd ()) file else file in
  let builtins = Words.create 16 in
  List.iter (fun (k, v) -> Words.replace builtins k v) (List.rev (config : config).builtins);
  { config; builtins; env; runner = { run = (fun _ -> invalid_arg "Cursor: no runner") }; frames = [ { toks; pos = 0; kind = Main; file; ctrl = []; scoped = false;
                 byref = [] } ];
    pending = []; last = Loc.none; files = [ abs ];
    deprecated = Hashtbl.create 8; braces = []; skipped = []; context = None; stop_at = None;
    handles = Hashtbl.create 4; supplied = 0; depth = 0; optional_sep = None;
    semi_probe = None }

let chain t =
  let l =
    List.filter_map
      (fun f ->
        match f.kind with
        | Main -> None
        | Include l -> Some ("included from", l)
        | Macro_call (name, l) -> Some ("in macro " ^ name ^ " called at", l))
      t.frames
  in
  (* recursion: fold runs of the same call site into one line *)
  let rec fold = function
    | ((w, l) as x) :: rest ->
        let rec count n = function
          | (w', l') :: r when w' = w && l' = l -> count (n + 1) r
          | r -> (n, r)
        in
        let n, rest = count 0 rest in
        if n = 0 then x :: fold rest
        else
          let w =
            if Filename.check_suffix w " at" then
              Printf.sprintf "%s %d times at" (Filename.chop_suffix w " at") (n + 1)
            else w
          in
          (w, l) :: fold rest
    | [] -> []
  in
  fold l

let fail t loc fmt = Diag.error ~chain:(chain t) loc fmt

exception Unsupported_use of Diag.t * Env.unsupported

let unsupported t loc (u : Env.unsupported) fmt =
  Printf.ksprintf
    (fun msg -> raise (Unsupported_use ({ Diag.loc; msg; chain = chain t }, u)))
    fmt

let unsupported_name t name (u : Env.unsupported) loc =
  match u.failure with
  | Some msg ->
      unsupported t loc u "%s cannot be used: its #declare at %s failed at %s: %s" name
        (Loc.to_string u.declared) (Loc.to_string u.feature_loc) msg
  | None ->
      unsupported t loc u "%s uses %s, which camlray does not support yet (%s at %s; %s declared at %s)"
        name u.feature u.feature (Loc.to_string u.feature_loc) name (Loc.to_string u.declared)
let top t = match t.frames with f :: _ -> f | [] -> assert false

(* ---------- raw token access ---------- *)

(* A finished include or macro frame is left: its scope ends and the
   macro's by-reference arguments are written back. An include file's
   #version stays in force after it (povray 3.7 does the same). *)
let leave t f =
  let back = List.filter_map (fun (p, n) -> Option.map (fun b -> (n, b)) (Env.find t.env p)) f.byref in
  if f.scoped then Env.pop_scope t.env;
  List.iter
    (fun (target, b) ->
      match target with
      | Name n -> Env.declare t.env n b
      | Element (a, i) -> a.(i) <- Some b)
    back;
  t.frames <- List.tl t.frames

let rec raw_next t =
  let f = top t in
  let tok = Toks.get f.toks f.pos in
  match tok.raw with
  | Eof when f.ctrl <> [] ->
      let d, l = opener (List.hd f.ctrl) in
      fail t l "this %s has no matching #end (the %s ends first)" d
        (match f.kind with Macro_call _ -> "macro" | _ -> "file")
  | Eof when f.kind <> Main ->
      leave t f;
      raw_next t
  | Eof -> tok
  | _ ->
      f.pos <- f.pos + 1;
      t.supplied <- t.supplied + 1;
      if t.supplied > t.config.limits.max_tokens then
        fail t tok.loc "parsing stopped after %d tokens (the limit)" t.config.limits.max_tokens;
      tok

let raw_peek t =
  let f = top t in
  Toks.get f.toks f.pos

let rec peek_past_ends t ~from =
  let f = top t in
  if f != from && f.kind <> Main && f.ctrl = [] && (Toks.get f.toks f.pos).raw = Eof then begin
    leave t f;
    peek_past_ends t ~from
  end
  else raw_peek t

let expect_raw t what pred =
  let tok = raw_next t in
  if not (pred tok.raw) then fail t tok.loc "expected %s, found %s" what (describe tok.raw);
  tok

let expect_tok t tk what = ignore (expect_raw t what (function Tok x -> x = tk | _ -> false))

let expect_ident t what =
  let tok = expect_raw t what (function Ident _ -> true | _ -> false) in
  match tok.raw with Ident s -> (s, tok.loc) | _ -> assert false

(* Skip tokens of the current frame up to the directive that ends the
   current block at depth 0: returns the directive name ("else", "elseif",
   "end", "case", "range", "break") and its token. [stop] says which
   names end the skip. *)
let opens = [ "if"; "ifdef"; "ifndef"; "while"; "for"; "switch"; "macro" ]

let skip_block t ~stop =
  let f = top t in
  let start = if f.pos > 0 then (Toks.get f.toks (f.pos - 1)).loc else Loc.none in
  let rec go depth =
    let tok = Toks.get f.toks f.pos in
    match tok.raw with
    | Eof -> fail t start "this directive has no matching #end"
    | Directive d ->
        f.pos <- f.pos + 1;
        if List.mem d opens then go (depth + 1)
        else if d = "end" then if depth = 0 then (d, tok) else go (depth - 1)
        else if depth = 0 && List.mem d stop then (d, tok)
        else go depth
    | _ ->
        f.pos <- f.pos + 1;
        go depth
  in
  go 0



(* Skip the rest of a phrase in the current frame: up to a ';' at depth
   0 (included), a directive or an unmatched closing bracket. A layered
   texture (texture {...} texture {...}) is skipped whole. *)
let skip_phrase t =
  let f = top t in
  let first = (Toks.get f.toks f.pos).raw in
  let rec go depth =
    let tok = Toks.get f.toks f.pos in
    let step () = f.pos <- f.pos + 1 in
    match tok.raw with
    | Eof -> ()
    | Directive _ when depth = 0 -> ()
    | Tok Parser.SEMI when depth = 0 -> step ()
    | Tok (Parser.LBRACE | Parser.LPAREN | Parser.LBRACKET) -> step (); go (depth + 1)
    | Tok (Parser.RBRACE | Parser.RPAREN | Parser.RBRACKET) when depth = 0 -> ()
    | Tok Parser.RBRACE when depth = 1 ->
        step ();
        if (Toks.get f.toks f.pos).raw = first && first = Tok Parser.TEXTURE then go 0
    | Tok (Parser.RBRACE | Parser.RPAREN | Parser.RBRACKET) -> step (); go (depth - 1)
    | _ -> step (); go depth
  in
  go 0

(* Where #include and file_exists look: the current folder, the scene's
   folder, then the include folders. *)
let candidates t name =
  let scene_dir =
    let main = List.find (fun f -> f.kind = Main) t.frames in
    Filename.dirname main.file
  in
  if not (Filename.is_relative name) then [ name ]
  else
    List.map (fun d -> if d = "." then name else Filename.concat d name)
      ("." :: scene_dir :: t.config.include_dirs)

(* Fail unless the scene may touch [path] (see Access). *)
let allowed t loc path =
  match Access.check t.config.access path with Ok () -> () | Error msg -> fail t loc "%s" msg

let find_file t name =
  List.find_opt (fun p -> Sys.file_exists p && not (Sys.is_directory p)) (candidates t name)

