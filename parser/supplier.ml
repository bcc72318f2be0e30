module I = Parser.MenhirInterpreter
open Lexer

type limits = {
  max_loop_iterations : int;
  max_macro_depth : int;
  max_include_depth : int;
  max_array_size : int;
}

let default_limits =
  { max_loop_iterations = 1_000_000; max_macro_depth = 200; max_include_depth = 64;
    max_array_size = 10_000_000 }

type config = { include_dirs : string list; limits : limits; builtins : (string * float) list }

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

type kind = Main | Include of Loc.t | Macro_call of string * Loc.t

type frame = {
  toks : token array;
  mutable pos : int;
  kind : kind;
  file : string;
  mutable ctrl : ctrl list;
  scoped : bool;
  version_at_entry : float;  (** restored when an included file ends *)
  byref : (string * string) list;
      (** macro parameters given a bare identifier, with that identifier:
          their final values are copied back when the macro ends
          (POV-Ray passes identifiers by reference) *)
}

type t = {
  config : config;
  env : Env.t;
  mutable frames : frame list;
  mutable pending : (Parser.token * Loc.t) list;  (** pushed-back tokens *)
  mutable last : Loc.t;
  mutable files : string list;
  handles : (string, handle) Hashtbl.t;  (** #fopen'ed files by identifier *)
  mutable braces : Loc.t list;  (** the '{' not yet closed, innermost first *)
  mutable context : string option;  (** what is being parsed, for messages *)
  deprecated : (string, string * bool * bool ref) Hashtbl.t;
      (** [#declare deprecated [once] "why" NAME = ...]: warn on use *)
}

let files_read t = List.rev t.files

let create config env ~file toks =
  let abs = if Filename.is_relative file then Filename.concat (Sys.getcwd ()) file else file in
  { config; env; frames = [ { toks; pos = 0; kind = Main; file; ctrl = []; scoped = false;
                 version_at_entry = Defaults.version (); byref = [] } ];
    pending = []; last = Loc.none; files = [ abs ];
    deprecated = Hashtbl.create 8; braces = []; context = None;
    handles = Hashtbl.create 4 }

let close_files t =
  Hashtbl.iter (fun _ h -> match h with Writing oc -> close_out_noerr oc | Reading _ -> ()) t.handles;
  Hashtbl.reset t.handles

let chain t =
  List.filter_map
    (fun f ->
      match f.kind with
      | Main -> None
      | Include l -> Some ("included from", l)
      | Macro_call (name, l) -> Some ("in macro " ^ name ^ " called at", l))
    t.frames

let fail t loc fmt = Diag.error ~chain:(chain t) loc fmt
let top t = match t.frames with f :: _ -> f | [] -> assert false

(* ---------- raw token access ---------- *)

let rec raw_next t =
  let f = top t in
  let tok = f.toks.(f.pos) in
  match tok.raw with
  | Eof when f.ctrl <> [] ->
      let d, l = opener (List.hd f.ctrl) in
      fail t l "this %s has no matching #end (the %s ends first)" d
        (match f.kind with Macro_call _ -> "macro" | _ -> "file")
  | Eof when f.kind <> Main ->
      let back = List.filter_map (fun (p, n) -> Option.map (fun b -> (n, b)) (Env.find t.env p)) f.byref in
      if f.scoped then Env.pop_scope t.env;
      List.iter (fun (n, b) -> Env.declare t.env n b) back;
      (match f.kind with
      | Include _ -> Defaults.restore_version f.version_at_entry
      | Main | Macro_call _ -> ());
      t.frames <- List.tl t.frames;
      raw_next t
  | Eof -> tok
  | _ ->
      f.pos <- f.pos + 1;
      tok

let raw_peek t =
  let f = top t in
  f.toks.(f.pos)

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
  let start = if f.pos > 0 then f.toks.(f.pos - 1).loc else Loc.none in
  let rec go depth =
    let tok = f.toks.(f.pos) in
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

(* ---------- typing identifiers ---------- *)

let token_of_decl : Decl.t -> Parser.token = function
  | Decl.Value (Value.Float f) -> Parser.FLOAT_ID f
  | Decl.Value (Value.Vector a) -> Parser.VECTOR_ID a
  | Decl.Value (Value.String s) -> Parser.STRING_ID s
  | Decl.Object o -> Parser.OBJECT_ID o
  | Decl.Pigment p -> Parser.PIGMENT_ID p
  | Decl.Finish f -> Parser.FINISH_ID f
  | Decl.Texture x -> Parser.TEXTURE_ID x
  | Decl.Interior i -> Parser.INTERIOR_ID i
  | Decl.Transform x -> Parser.TRANSFORM_ID x
  | Decl.Camera c -> Parser.CAMERA_ID c
  | Decl.Function f -> Parser.FUNCTION_ID f

let suggest t name =
  let d a b =
    (* Levenshtein distance, small strings *)
    let la = String.length a and lb = String.length b in
    let m = Array.make_matrix (la + 1) (lb + 1) 0 in
    for i = 0 to la do m.(i).(0) <- i done;
    for j = 0 to lb do m.(0).(j) <- j done;
    for i = 1 to la do
      for j = 1 to lb do
        let c = if a.[i - 1] = b.[j - 1] then 0 else 1 in
        m.(i).(j) <- min (min (m.(i - 1).(j) + 1) (m.(i).(j - 1) + 1)) (m.(i - 1).(j - 1) + c)
      done
    done;
    m.(la).(lb)
  in
  let best =
    List.fold_left
      (fun acc n ->
        let k = d (String.lowercase_ascii name) (String.lowercase_ascii n) in
        match acc with
        | Some (_, k') when k' <= k -> acc
        | _ -> if k <= max 1 (String.length name / 3) then Some (n, k) else acc)
      None (Env.names t.env)
  in
  match best with Some (n, _) -> Printf.sprintf " (did you mean %s?)" n | None -> ""

(* ---------- the sub-parse driver ---------- *)

let acceptable_probe : Parser.token list =
  Parser.[ LBRACE; RBRACE; LPAREN; RPAREN; LT; GT; COMMA; SEMI; FLOAT 0.; STRING "";
           UNDEFINED_ID ""; EQ ]

let rec next t : Parser.token * Loc.t =
  match t.pending with
  | x :: rest ->
      t.pending <- rest;
      x
  | [] -> (
      let tok = raw_next t in
      match tok.raw with
      | Eof -> (Parser.EOF, tok.loc)
      | Tok x ->
          (match x with
          | Parser.LBRACE -> t.braces <- tok.loc :: t.braces
          | Parser.RBRACE -> (match t.braces with _ :: r -> t.braces <- r | [] -> ())
          | _ -> ());
          (x, tok.loc)
      | Directive d ->
          directive t d tok.loc;
          next t
      | Ident name -> ident t name tok.loc)

and ident t name loc =
  match List.assoc_opt name t.config.builtins with
  | Some v -> (Parser.FLOAT v, loc)
  | None when name = "version" -> (Parser.FLOAT (Defaults.version ()), loc)
  | None -> (
      (match Hashtbl.find_opt t.deprecated name with
      | Some (msg, once, warned) when not (once && !warned) ->
          warned := true;
          Diag.warning loc (Printf.sprintf "%s is deprecated: %s" name msg)
      | _ -> ());
      match Env.find t.env name with
      | Some (Env.Decl d) -> (token_of_decl d, loc)
      | Some (Env.Macro m) ->
          call_macro t m loc;
          next t
      | Some (Env.Array a) -> array_access t name a loc
      | None ->
          if name = "default" && (raw_peek t).raw = Tok Parser.LBRACE then begin
            (* 'default { ... }' without '#': POV-Ray accepts it too *)
            parse t Parser.Incremental.default_body;
            next t
          end
          else if name = "function" then (Parser.FUNCTION_LIT (function_lit t loc), loc)
          else if name = "file_exists" then begin
            expect_tok t Parser.LPAREN "'(' after file_exists";
            let file = parse t Parser.Incremental.string_arg in
            expect_tok t Parser.RPAREN "')'";
            (Parser.FLOAT (if find_file t file <> None then 1. else 0.), loc)
          end
          else if name = "defined" || name = "dimensions" || name = "dimension_size" then
            (Parser.FLOAT (array_query t name loc), loc)
          else if name = "array" then fail t loc "arrays can only be created with #declare NAME = array[N]"
          else if Lexer.pov_reserved name then
            fail t loc "%s is not supported by camlray" name
          else (Parser.UNDEFINED_ID name, loc))

(* function [(params)] { body }: the body is read here, token by token,
   and compiled by Fnparse; directives may not stand inside it. *)
and function_lit t loc =
  let params =
    match (raw_peek t).raw with
    | Tok Parser.LPAREN ->
        ignore (raw_next t);
        let rec go acc =
          let tok = raw_next t in
          match Fnparse.word tok.raw with
          | Some p -> (
              if List.mem p acc then fail t tok.loc "parameter %s is listed twice" p;
              let sep = raw_next t in
              match sep.raw with
              | Tok Parser.COMMA -> go (p :: acc)
              | Tok Parser.RPAREN -> List.rev (p :: acc)
              | r -> fail t sep.loc "expected ',' or ')' in the parameter list, found %s" (describe r))
          | None -> (
              match tok.raw with
              | Tok Parser.RPAREN when acc = [] -> []
              | r -> fail t tok.loc "expected a parameter name, found %s" (describe r))
        in
        go []
    | _ -> [ "x"; "y"; "z" ]
  in
  expect_tok t Parser.LBRACE "'{' to open the function's body";
  match (raw_peek t).raw with
  | Tok Parser.TRANSFORM ->
      if params <> [ "x"; "y"; "z" ] then fail t loc "a transform function takes no parameter list";
      let tr = parse t Parser.Incremental.transform_arg in
      expect_tok t Parser.RBRACE "'}' to close the function";
      Fn.of_transform tr
  | _ ->
  let rec body depth acc =
    let tok = raw_next t in
    match tok.raw with
    | Eof -> fail t loc "this function's body has no closing '}'"
    | Directive d -> fail t tok.loc "#%s cannot stand inside a function's body" d
    | Tok Parser.LBRACE -> body (depth + 1) (tok :: acc)
    | Tok Parser.RBRACE ->
        if depth = 0 then List.rev ({ raw = Eof; loc = tok.loc } :: acc)
        else body (depth - 1) (tok :: acc)
    | _ -> body depth (tok :: acc)
  in
  let toks = Array.of_list (body 0 []) in
  if Array.length toks = 1 then fail t loc "a function's body cannot be empty";
  let resolve name =
    match List.assoc_opt name t.config.builtins with
    | Some v -> Fnparse.Const v
    | None -> (
        match Env.find t.env name with
        | Some (Env.Decl (Decl.Value (Value.Float f))) -> Fnparse.Const f
        | Some (Env.Decl (Decl.Value (Value.Vector a))) -> Fnparse.Vec a
        | Some (Env.Decl (Decl.Function f)) -> Fnparse.Func f
        | _ -> Fnparse.Unknown)
  in
  Fnparse.compile ~resolve ~params toks

(* defined(NAME), defined(NAME[i]...), dimensions(ARRAY),
   dimension_size(ARRAY, DIM) *)
and array_query t what loc =
  expect_tok t Parser.LPAREN (Printf.sprintf "'(' after %s" what);
  let name, nloc = expect_ident t "an identifier" in
  let rec element b =
    match (b, (raw_peek t).raw) with
    | Some (Env.Array a), Tok Parser.LBRACKET ->
        ignore (raw_next t);
        let i = Value.to_int nloc (parse t Parser.Incremental.expr_then_rbracket) in
        if i < 0 || i >= Array.length a then
          fail t nloc "index %d is outside the array %s (size %d)" i name (Array.length a);
        element a.(i)
    | _, Tok Parser.LBRACKET -> fail t nloc "%s is not an array" name
    | _ -> b
  in
  let b = match Env.find t.env name with
    | Some b -> Some b
    | None ->
        if List.mem_assoc name t.config.builtins || Hashtbl.mem t.handles name then
          Some (Env.Decl (Decl.Value (Value.Float 0.)))
        else None
  in
  let result =
    match what with
    | "defined" -> if element b = None then 0. else 1.
    | _ -> (
        let a = match b with
          | Some (Env.Array a) -> a
          | _ -> fail t nloc "%s: %s is not an array" what name
        in
        let rec dims a =
          Array.length a :: (match if Array.length a > 0 then a.(0) else None with
            | Some (Env.Array a') -> dims a' | _ -> [])
        in
        let ds = dims a in
        if what = "dimensions" then float_of_int (List.length ds)
        else begin
          expect_tok t Parser.COMMA "','";
          let d = Value.to_int loc (parse t Parser.Incremental.expr_then_rparen) in
          (* POV-Ray: 0 outside 1 .. dimensions *)
          float_of_int (if d < 1 || d > List.length ds then 0 else List.nth ds (d - 1))
        end)
  in
  if what <> "dimension_size" then expect_tok t Parser.RPAREN "')'";
  result

and array_access t name a loc =
  let tok = raw_peek t in
  match tok.raw with
  | Tok Parser.LBRACKET ->
      ignore (raw_next t);
      let i = Value.to_int loc (parse t Parser.Incremental.expr_then_rbracket) in
      if i < 0 || i >= Array.length a then
        fail t loc "index %d is outside the array %s (size %d)" i name (Array.length a);
      (match a.(i) with
      | None -> fail t loc "element %s[%d] has not been set" name i
      | Some (Env.Decl d) -> (token_of_decl d, loc)
      | Some (Env.Array a') -> array_access t (Printf.sprintf "%s[%d]" name i) a' loc
      | Some (Env.Macro _) -> fail t loc "an array cannot hold a macro")
  | _ -> fail t loc "the array %s must be indexed: %s[...]" name name

and parse : 'a. t -> (Lexing.position -> 'a I.checkpoint) -> 'a =
 fun t start ->
  let pos = (top t).toks.((top t).pos).loc.start in
  let rec loop cp last shifted =
    match cp with
    | I.InputNeeded _ ->
        let tok, loc = next t in
        t.last <- loc;
        loop (I.offer cp (tok, loc.start, loc.stop)) (Some (tok, loc)) false
    | I.Shifting _ -> loop (I.resume cp) last true
    | I.AboutToReduce _ -> loop (I.resume cp) last shifted
    | I.HandlingError env -> syntax_error t env last
    | I.Accepted v ->
        (match last with
        | Some x when not shifted -> t.pending <- x :: t.pending
        | _ -> ());
        v
    | I.Rejected -> fail t t.last "syntax error"
  in
  loop (start pos) None true

and syntax_error : 'a. t -> 'a I.env -> (Parser.token * Loc.t) option -> 'b =
 fun t env last ->
  let tok, loc = match last with Some x -> x | None -> (Parser.EOF, t.last) in
  match tok with
  | Parser.UNDEFINED_ID name -> fail t loc "undefined identifier %s%s" name (suggest t name)
  | _ ->
      let found = describe (Tok tok) in
      let expected =
        List.filter_map
          (fun probe ->
            let cp = I.input_needed env in
            if I.acceptable cp probe loc.start then
              Some
                (match probe with
                | Parser.FLOAT _ -> "a number"
                | Parser.STRING _ -> "a string"
                | Parser.UNDEFINED_ID _ -> "an identifier"
                | _ -> describe (Tok probe))
            else None)
          acceptable_probe
      in
      let semi = List.mem "';'" expected in
      let msg =
        match Messages.message (I.current_state_number env) with
        | m -> String.trim m
        | exception Not_found -> (
            match expected with
            | [] -> "unexpected " ^ found
            | _ when semi -> Printf.sprintf "expected an operator or ';', found %s" found
            | l -> Printf.sprintf "expected %s, found %s" (String.concat " or " l) found)
      in
      let hint =
        match (t.context, tok, t.braces) with
        | Some c, _, _ when semi -> Printf.sprintf " (%s ends with ';')" c
        | _, Parser.EOF, b :: _ ->
            Printf.sprintf " (the '{' at line %d, column %d is not closed)" (Loc.line b) (Loc.col b)
        | _ -> ""
      in
      fail t loc "%s%s" msg hint

(* ---------- directives ---------- *)

and directive t d loc =
  let f = top t in
  match d with
  | "version" ->
      let v = Value.to_float loc (parse t Parser.Incremental.expr_then_semi) in
      Defaults.set_version v
  | "declare" | "local" -> declare t ~local:(d = "local") loc
  | "undef" ->
      let name, _ = expect_ident t "an identifier after #undef" in
      Env.undef t.env name
  | "include" -> include_file t loc
  | "if" ->
      let c = Value.to_bool loc (parse t Parser.Incremental.paren_expr) in
      enter_if t loc c
  | "ifdef" | "ifndef" ->
      let defined = array_query t "defined" loc = 1. in
      enter_if t loc (if d = "ifdef" then defined else not defined)
  | "elseif" | "else" -> (
      match f.ctrl with
      | In_if _ :: rest ->
          (* the taken branch ends here: skip to #end *)
          f.ctrl <- rest;
          skip_to_end t
      | In_switch _ :: _ when d = "else" -> () (* falling through into #else *)
      | _ -> fail t loc "#%s without a matching #if" d)
  | "end" -> end_block t loc
  | "while" ->
      let cond_pos = f.pos in
      let c = Value.to_bool loc (parse t Parser.Incremental.paren_expr) in
      if c then f.ctrl <- In_while { cond_pos; count = 1; wloc = loc } :: f.ctrl else skip_to_end t
  | "for" -> for_loop t loc
  | "switch" -> switch t loc
  | "case" | "range" -> (
      match f.ctrl with
      | In_switch _ :: _ ->
          (* fall through: skip this clause's condition *)
          skip_condition t
      | _ -> fail t loc "#%s outside #switch" d)
  | "break" -> break t loc
  | "macro" -> define_macro t loc
  | "debug" | "warning" | "error" ->
      let s = parse t Parser.Incremental.string_arg in
      if d = "debug" then (prerr_string s; flush stderr)
      else if d = "warning" then Diag.warning loc s
      else fail t loc "#error: %s" s
  | "default" -> parse t Parser.Incremental.default_body
  | "fopen" -> fopen t loc
  | "fclose" ->
      let name, nloc = expect_ident t "a file identifier after #fclose" in
      (match Hashtbl.find_opt t.handles name with
      | Some (Writing oc) -> close_out oc
      | Some (Reading _) -> ()
      | None -> fail t nloc "%s is not an open file" name);
      Hashtbl.remove t.handles name
  | "write" -> write t loc
  | "read" -> read t loc
  | _ -> fail t loc "unknown directive #%s" d

(* #fopen ID "file" read|write|append *)
and fopen t loc =
  let name, nloc = expect_ident t "a file identifier after #fopen" in
  if Hashtbl.mem t.handles name then fail t nloc "the file %s is already open" name;
  let file = parse t Parser.Incremental.string_arg in
  let mode, mloc = expect_ident t "read, write or append" in
  match mode with
  | "read" -> (
      match find_file t file with
      | None -> fail t loc "cannot find %S to read" file
      | Some path ->
          let text =
            try In_channel.with_open_bin path In_channel.input_all
            with Sys_error e -> fail t loc "cannot read %s: %s" path e
          in
          Hashtbl.replace t.handles name (Reading { data = Lexer.tokenize ~file:path text; at = 0 }))
  | "write" | "append" ->
      let flags = if mode = "write" then [ Open_wronly; Open_creat; Open_trunc; Open_binary ]
        else [ Open_wronly; Open_creat; Open_append; Open_binary ] in
      let oc = try open_out_gen flags 0o644 file with Sys_error e -> fail t loc "cannot open %s: %s" file e in
      Hashtbl.replace t.handles name (Writing oc)
  | m -> fail t mloc "expected read, write or append, found %s" m

(* #write (ID, item, ...): strings as they are, floats as %g, vectors as
   <%g,%g,...> followed by a space (POV-Ray's format) *)
and write t loc =
  expect_tok t Parser.LPAREN "'(' after #write";
  let name, nloc = expect_ident t "a file identifier" in
  let oc = match Hashtbl.find_opt t.handles name with
    | Some (Writing oc) -> oc
    | Some (Reading _) -> fail t nloc "%s was opened for reading" name
    | None -> fail t nloc "%s is not an open file" name
  in
  expect_tok t Parser.COMMA "','";
  let rec items () =
    let d, closed = parse t Parser.Incremental.macro_arg in
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
and read t loc =
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
    expect_tok t Parser.COMMA "','";
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

and enter_if t loc c =
  let f = top t in
  if c then f.ctrl <- In_if loc :: f.ctrl
  else
    let rec seek () =
      match skip_block t ~stop:[ "else"; "elseif" ] with
      | "else", _ -> f.ctrl <- In_if loc :: f.ctrl
      | "elseif", tok ->
          if Value.to_bool tok.loc (parse t Parser.Incremental.paren_expr) then
            f.ctrl <- In_if loc :: f.ctrl
          else seek ()
      | _ -> ()
    in
    seek ()

and skip_to_end t = ignore (skip_block t ~stop:[])

and skip_condition t =
  let tok = expect_raw t "'('" (function Tok Parser.LPAREN -> true | _ -> false) in
  let f = top t in
  let rec go depth =
    match f.toks.(f.pos).raw with
    | Eof -> fail t tok.loc "unclosed '('"
    | Tok Parser.LPAREN -> f.pos <- f.pos + 1; go (depth + 1)
    | Tok Parser.RPAREN -> f.pos <- f.pos + 1; if depth > 0 then go (depth - 1)
    | _ -> f.pos <- f.pos + 1; go depth
  in
  go 0

and end_block t loc =
  let f = top t in
  match f.ctrl with
  | [] -> fail t loc "#end without an open #if, #while, #for, #switch or #macro"
  | (In_if _ | In_switch _) :: rest -> f.ctrl <- rest
  | (In_while w as c) :: rest ->
      f.ctrl <- rest;
      let end_pos = f.pos in
      f.pos <- w.cond_pos;
      let cond = Value.to_bool loc (parse t Parser.Incremental.paren_expr) in
      if cond then begin
        if w.count >= t.config.limits.max_loop_iterations then
          fail t loc "#while loop stopped after %d iterations (the limit; raise it with --max-loop)"
            w.count;
        w.count <- w.count + 1;
        f.ctrl <- c :: rest
      end
      else f.pos <- end_pos
  | (In_for r as c) :: rest ->
      let v =
        match Env.find t.env r.var with
        | Some (Env.Decl (Decl.Value (Value.Float v))) -> v +. r.step
        | _ -> fail t loc "the #for variable %s was changed to something else than a float" r.var
      in
      Env.declare t.env r.var (Env.Decl (Decl.Value (Value.Float v)));
      if (r.step > 0. && v <= r.stop +. 1e-12) || (r.step < 0. && v >= r.stop -. 1e-12) then begin
        if r.count >= t.config.limits.max_loop_iterations then
          fail t loc "#for loop stopped after %d iterations (the limit; raise it with --max-loop)"
            r.count;
        r.count <- r.count + 1;
        f.pos <- r.body_pos
      end
      else f.ctrl <- rest;
      ignore c

and for_loop t loc =
  expect_tok t Parser.LPAREN "'(' after #for";
  let var, _ = expect_ident t "the loop variable" in
  expect_tok t Parser.COMMA "','";
  let start = Value.to_float loc (parse t Parser.Incremental.expr_then_comma) in
  let stop, closed = parse t Parser.Incremental.macro_arg in
  let num d = match d with Decl.Value v -> Value.to_float loc v | _ -> fail t loc "#for bounds must be floats" in
  let stop = num stop in
  let step = if closed then 1. else Value.to_float loc (parse t Parser.Incremental.expr_then_rparen) in
  if step = 0. then fail t loc "#for step cannot be 0";
  Env.declare t.env var (Env.Decl (Decl.Value (Value.Float start)));
  let f = top t in
  if (step > 0. && start <= stop) || (step < 0. && start >= stop) then
    f.ctrl <- In_for { var; stop; step; body_pos = f.pos; count = 1; floc = loc } :: f.ctrl
  else skip_to_end t

and switch t loc =
  let v = Value.to_float loc (parse t Parser.Incremental.paren_expr) in
  let f = top t in
  let rec seek () =
    match skip_block t ~stop:[ "case"; "range"; "else" ] with
    | "case", tok ->
        let c = Value.to_float tok.loc (parse t Parser.Incremental.paren_expr) in
        if Float.abs (c -. v) <= 1e-10 then f.ctrl <- In_switch loc :: f.ctrl else seek ()
    | "range", tok ->
        expect_tok t Parser.LPAREN "'(' after #range";
        let lo = Value.to_float tok.loc (parse t Parser.Incremental.expr_then_comma) in
        let hi = Value.to_float tok.loc (parse t Parser.Incremental.expr_then_rparen) in
        if v >= lo && v <= hi then f.ctrl <- In_switch loc :: f.ctrl else seek ()
    | "else", _ -> f.ctrl <- In_switch loc :: f.ctrl
    | _ -> ()
  in
  (* the first clause starts right away: no tokens may stand before it *)
  seek ()

and break t loc =
  let f = top t in
  let rec unwind = function
    | In_switch _ :: rest -> f.ctrl <- rest; skip_to_end t
    | In_if _ :: rest -> f.ctrl <- rest; skip_to_end t; unwind rest
    | (In_while _ | In_for _) :: rest -> f.ctrl <- rest; skip_to_end t
    | [] -> fail t loc "#break outside #switch or a loop"
  in
  unwind f.ctrl

and declare t ~local loc =
  let name, nloc = expect_ident t "an identifier after #declare" in
  let name, nloc =
    if name <> "deprecated" then (name, nloc)
    else begin
      (* #declare deprecated [once] "message" NAME = ... *)
      let once =
        match (raw_peek t).raw with Ident "once" -> ignore (raw_next t); true | _ -> false
      in
      let msg =
        match (raw_next t).raw with
        | Tok (Parser.STRING m) -> m
        | r -> fail t nloc "expected the deprecation message (a string), found %s" (describe r)
      in
      let name, nloc = expect_ident t "the identifier being declared" in
      Hashtbl.replace t.deprecated name (msg, once, ref false);
      (name, nloc)
    end
  in
  if Lexer.pov_reserved name then fail t nloc "%s is a reserved word and cannot be declared" name;
  let bind b = if local then Env.local t.env name b else Env.declare t.env name b in
  match (raw_peek t).raw with
  | Tok Parser.LBRACKET -> (
      (* element assignment: NAME[i]... = value *)
      let rec target a =
        ignore (raw_next t);
        let i = Value.to_int loc (parse t Parser.Incremental.expr_then_rbracket) in
        if i < 0 || i >= Array.length a then
          fail t nloc "index %d is outside the array %s (size %d)" i name (Array.length a);
        match (raw_peek t).raw with
        | Tok Parser.LBRACKET -> (
            match a.(i) with
            | Some (Env.Array a') -> target a'
            | _ -> fail t nloc "%s has fewer dimensions than indices" name)
        | _ -> (a, i)
      in
      match Env.find t.env name with
      | Some (Env.Array a) ->
          let a, i = target a in
          expect_tok t Parser.EQ "'='";
          a.(i) <- Some (Env.Decl (rhs t))
      | _ -> fail t nloc "%s is not an array" name)
  | _ -> (
      expect_tok t Parser.EQ "'=' after the identifier";
      match (raw_peek t).raw with
      | Ident "array" ->
          ignore (raw_next t);
          bind (Env.Array (new_array t loc));
          (match (raw_peek t).raw with Tok Parser.SEMI -> ignore (raw_next t) | _ -> ())
      | _ -> (
          (* #declare A = B; for B a whole array or a function (not a call) *)
          let f = top t in
          let whole =
            match f.toks.(f.pos).raw with
            | Ident n when t.pending = [] && f.pos + 1 < Array.length f.toks -> (
                match (Env.find t.env n, f.toks.(f.pos + 1).raw) with
                | Some (Env.Array a), r when r <> Tok Parser.LBRACKET -> Some (Env.Array (copy_array a))
                | Some (Env.Decl (Decl.Function _) as b), r when r <> Tok Parser.LPAREN -> Some b
                | _ -> None)
            | _ -> None
          in
          match whole with
          | Some b ->
              f.pos <- f.pos + 1;
              bind b;
              (match (raw_peek t).raw with Tok Parser.SEMI -> ignore (raw_next t) | _ -> ())
          | None -> bind (Env.Decl (rhs t))))

and copy_array a =
  Array.map (function Some (Env.Array a') -> Some (Env.Array (copy_array a')) | x -> x) a

(* A string #declare may end without ';' (POV-Ray's rule). A string
   expression is one term (a literal, a string identifier or a string
   function's call), so whether a ';' follows can be seen in the raw
   tokens; without one, the string is parsed with no lookahead, so that
   a directive right after it runs only once the name is bound. *)
and string_without_semi t =
  let f = top t in
  let at i = if i < Array.length f.toks then f.toks.(i).raw else Eof in
  let after_term =
    if t.pending <> [] then None
    else
      match at f.pos with
      | Tok (Parser.STRING _) -> Some (f.pos + 1)
      | Ident n -> (
          match Env.find t.env n with
          | Some (Env.Decl (Decl.Value (Value.String _))) -> Some (f.pos + 1)
          | _ -> None)
      | Tok (Parser.FUNC name) when List.mem name string_functions && at (f.pos + 1) = Tok Parser.LPAREN ->
          let rec close i depth =
            match at i with
            | Tok Parser.LPAREN -> close (i + 1) (depth + 1)
            | Tok Parser.RPAREN -> if depth = 1 then Some (i + 1) else close (i + 1) (depth - 1)
            | Eof | Directive _ -> None
            | _ -> close (i + 1) depth
          in
          close (f.pos + 1) 0
      | _ -> None
  in
  match after_term with
  | Some i -> ( match at i with Tok (Parser.SEMI | Parser.PLUS | Parser.MINUS | Parser.STAR | Parser.SLASH) -> false | _ -> true)
  | None -> false

and string_functions = [ "concat"; "str"; "chr"; "substr"; "strupr"; "strlwr"; "vstr" ]

and rhs t =
  let saved = t.context in
  t.context <- Some "#declare of a float, vector or colour";
  let d =
    Fun.protect ~finally:(fun () -> t.context <- saved) (fun () ->
        if string_without_semi t then Decl.Value (Value.String (parse t Parser.Incremental.string_arg))
        else parse t Parser.Incremental.declare_rhs)
  in
  (match d with
  | Decl.Value _ -> ()
  | _ -> ( match (raw_peek t).raw with Tok Parser.SEMI -> ignore (raw_next t) | _ -> ()));
  d

and new_array t loc =
  let rec dims acc =
    match (raw_peek t).raw with
    | Tok Parser.LBRACKET ->
        ignore (raw_next t);
        let n = Value.to_int loc (parse t Parser.Incremental.expr_then_rbracket) in
        if n <= 0 then fail t loc "array size must be positive, found %d" n;
        dims (n :: acc)
    | _ -> List.rev acc
  in
  let ds = dims [] in
  if ds = [] then fail t loc "expected [size] after array";
  let total = List.fold_left ( * ) 1 ds in
  if total > t.config.limits.max_array_size then
    fail t loc "array of %d elements exceeds the limit %d" total t.config.limits.max_array_size;
  let rec make = function
    | [] -> assert false
    | [ n ] -> Array.make n None
    | n :: rest -> Array.init n (fun _ -> Some (Env.Array (make rest)))
  in
  let a = make ds in
  (match (raw_peek t).raw with
  | Tok Parser.LBRACE -> fill t loc a ds
  | _ -> ());
  a

and fill t loc a ds =
  ignore (raw_next t);
  (* at '{' already consumed *)
  match ds with
  | [ n ] ->
      let rec go i =
        if i >= n then
          (* a trailing comma before '}' is allowed *)
          match (raw_peek t).raw with
          | Tok Parser.RBRACE -> ignore (raw_next t)
          | _ -> fail t loc "too many initialisers (the array has %d elements)" n
        else
          let d, closed = parse t Parser.Incremental.array_elem in
          a.(i) <- Some (Env.Decl d);
          if not closed then go (i + 1)
          else if i + 1 <> n then fail t loc "%d initialisers for an array of %d" (i + 1) n
      in
      go 0
  | n :: rest ->
      for i = 0 to n - 1 do
        (match a.(i) with
        | Some (Env.Array sub) ->
            (match (raw_peek t).raw with
            | Tok Parser.LBRACE -> fill t loc sub rest
            | r -> fail t loc "expected '{' for a row of the array, found %s" (describe r))
        | _ -> assert false);
        let sep = raw_next t in
        match sep.raw with
        | Tok Parser.COMMA when i < n - 1 -> ()
        | Tok Parser.RBRACE when i = n - 1 -> ()
        | r -> fail t sep.loc "expected %s, found %s" (if i < n - 1 then "','" else "'}'") (describe r)
      done
  | [] -> assert false

and define_macro t loc =
  let name, _ = expect_ident t "the macro's name" in
  expect_tok t Parser.LPAREN "'(' after the macro name";
  let rec params acc =
    let tok = raw_next t in
    match tok.raw with
    | Tok Parser.RPAREN when acc = [] -> []
    | Ident p -> (
        let sep = raw_next t in
        match sep.raw with
        | Tok Parser.COMMA -> params (p :: acc)
        | Tok Parser.RPAREN -> List.rev (p :: acc)
        | r -> fail t sep.loc "expected ',' or ')' in the parameter list, found %s" (describe r))
    | r -> fail t tok.loc "expected a parameter name, found %s" (describe r)
  in
  let ps = params [] in
  let f = top t in
  let body_start = f.pos in
  ignore (skip_block t ~stop:[]);
  let body_end = f.pos - 1 in
  let eof = { raw = Eof; loc = f.toks.(body_end).loc } in
  let body = Array.append (Array.sub f.toks body_start (body_end - body_start)) [| eof |] in
  Env.declare t.env name (Env.Macro { name; params = ps; body; file = f.file; mloc = loc })

and call_macro t (m : Env.macro) loc =
  let depth = List.length (List.filter (fun f -> match f.kind with Macro_call _ -> true | _ -> false) t.frames) in
  if depth >= t.config.limits.max_macro_depth then
    fail t loc "macro %s: calls nested deeper than %d (the limit; raise it with --max-macro-depth)"
      m.name t.config.limits.max_macro_depth;
  let lp = raw_next t in
  (match lp.raw with
  | Tok Parser.LPAREN -> ()
  | r -> fail t lp.loc "expected '(' after the macro name %s, found %s" m.name (describe r));
  let args =
    match m.params with
    | [] ->
        expect_tok t Parser.RPAREN "')' (this macro takes no arguments)";
        []
    | ps ->
        let rec go acc = function
          | [] -> List.rev acc
          | p :: rest ->
              let arg, closed = macro_arg t in
              if closed && rest <> [] then
                fail t loc "macro %s expects %d arguments, got %d" m.name (List.length ps)
                  (List.length acc + 1);
              if (not closed) && rest = [] then
                fail t loc "macro %s expects %d arguments, got more" m.name (List.length ps);
              go ((p, arg) :: acc) rest
        in
        go [] ps
  in
  Env.push_scope t.env;
  List.iter (fun (p, (b, _)) -> Env.local t.env p b) args;
  let byref = List.filter_map (fun (p, (_, n)) -> Option.map (fun n -> (p, n)) n) args in
  t.frames <-
    { toks = m.body; pos = 0; kind = Macro_call (m.name, loc); file = m.file; ctrl = [];
      scoped = true; version_at_entry = Defaults.version (); byref }
    :: t.frames

(* One macro argument and whether it closed the list. A bare declared
   identifier (NAME followed by ',' or ')') is passed by reference, as in
   POV-Ray: arrays as themselves, other values copied back at the end. *)
and macro_arg t =
  let f = top t in
  let bare =
    match f.toks.(f.pos).raw with
    | Ident n when t.pending = [] && f.pos + 1 < Array.length f.toks -> (
        match (f.toks.(f.pos + 1).raw, Env.find t.env n) with
        | Tok ((Parser.COMMA | Parser.RPAREN) as sep), Some ((Env.Array _ | Env.Decl _) as b) ->
            f.pos <- f.pos + 2;
            Some ((b, Some n), sep = Parser.RPAREN)
        | _ -> None)
    | _ -> None
  in
  match bare with
  | Some x -> x
  | None ->
      let d, closed = parse t Parser.Incremental.macro_arg in
      ((Env.Decl d, None), closed)

(* Where #include and file_exists look: the current folder, the scene's
   folder, then the include folders. *)
and candidates t name =
  let scene_dir =
    let main = List.find (fun f -> f.kind = Main) t.frames in
    Filename.dirname main.file
  in
  if not (Filename.is_relative name) then [ name ]
  else
    List.map (fun d -> if d = "." then name else Filename.concat d name)
      ("." :: scene_dir :: t.config.include_dirs)

and find_file t name =
  List.find_opt (fun p -> Sys.file_exists p && not (Sys.is_directory p)) (candidates t name)

and include_file t loc =
  let tok = raw_next t in
  let name =
    match tok.raw with
    | Tok (Parser.STRING s) -> s
    | Ident _ | Tok (Parser.FUNC _) ->
        (top t).pos <- (top t).pos - 1;
        parse t Parser.Incremental.string_arg
    | r -> fail t tok.loc "expected a file name after #include, found %s" (describe r)
  in
  let depth = List.length (List.filter (fun f -> match f.kind with Include _ -> true | _ -> false) t.frames) in
  if depth >= t.config.limits.max_include_depth then
    fail t loc "#include nested deeper than %d files" t.config.limits.max_include_depth;
  let name = if Filename.extension name = "" then name ^ ".inc" else name in
  match find_file t name with
  | None ->
      fail t tok.loc "cannot find include file %S (looked in %s)" name
        (String.concat ", " (List.sort_uniq compare (List.map Filename.dirname (candidates t name))))
  | Some path ->
      let abs = if Filename.is_relative path then Filename.concat (Sys.getcwd ()) path else path in
      if List.exists (fun f -> f.file = path && f.kind <> Main) t.frames then
        fail t tok.loc "include cycle: %S includes itself" name;
      let text =
        try In_channel.with_open_bin path In_channel.input_all
        with Sys_error e -> fail t tok.loc "cannot read %s: %s" path e
      in
      let toks = Lexer.tokenize ~file:path text in
      if not (List.mem abs t.files) then t.files <- abs :: t.files;
      Env.push_scope t.env;
      t.frames <-
        { toks; pos = 0; kind = Include loc; file = path; ctrl = []; scoped = true;
          version_at_entry = Defaults.version (); byref = [] }
        :: t.frames
