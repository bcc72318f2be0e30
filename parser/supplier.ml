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
  | In_if  (** executing a taken branch of #if/#ifdef/#ifndef *)
  | In_while of { cond_pos : int; mutable count : int }
  | In_for of { var : string; stop : float; step : float; body_pos : int; mutable count : int }
  | In_switch  (** executing a matched clause *)

type kind = Main | Include of Loc.t | Macro_call of string * Loc.t

type frame = {
  toks : token array;
  mutable pos : int;
  kind : kind;
  file : string;
  mutable ctrl : ctrl list;
  scoped : bool;
}

type t = {
  config : config;
  env : Env.t;
  mutable frames : frame list;
  mutable pending : (Parser.token * Loc.t) list;  (** pushed-back tokens *)
  mutable last : Loc.t;
  mutable files : string list;
}

let files_read t = List.rev t.files

let create config env ~file toks =
  let abs = if Filename.is_relative file then Filename.concat (Sys.getcwd ()) file else file in
  { config; env; frames = [ { toks; pos = 0; kind = Main; file; ctrl = []; scoped = false } ];
    pending = []; last = Loc.none; files = [ abs ] }

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
  | Eof when f.kind <> Main ->
      if f.ctrl <> [] then fail t tok.loc "missing #end: a directive opened in this %s is not closed"
          (match f.kind with Macro_call _ -> "macro" | _ -> "file");
      if f.scoped then Env.pop_scope t.env;
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
  | Decl.Color_map m -> Parser.COLOR_MAP_ID m
  | Decl.Normal n -> Parser.NORMAL_ID n
  | Decl.Material m -> Parser.MATERIAL_ID m
  | Decl.Sky_sphere k -> Parser.SKY_SPHERE_ID k

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
      | Tok x -> (x, tok.loc)
      | Directive d ->
          directive t d tok.loc;
          next t
      | Ident name -> ident t name tok.loc)

and ident t name loc =
  match List.assoc_opt name t.config.builtins with
  | Some v -> (Parser.FLOAT v, loc)
  | None when name = "version" -> (Parser.FLOAT (Defaults.version ()), loc)
  | None -> (
      match Env.find t.env name with
      | Some (Env.Decl d) -> (token_of_decl d, loc)
      | Some (Env.Macro m) ->
          call_macro t m loc;
          next t
      | Some (Env.Array a) -> array_access t name a loc
      | None ->
          if name = "array" then fail t loc "arrays can only be created with #declare NAME = array[N]"
          else if Lexer.pov_reserved name then
            fail t loc "%s is not supported by camlray" name
          else (Parser.UNDEFINED_ID name, loc))

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
            if I.acceptable cp probe loc.start then Some (describe (Tok probe)) else None)
          acceptable_probe
      in
      let msg =
        match Messages.message (I.current_state_number env) with
        | m -> String.trim m
        | exception Not_found -> (
            match expected with
            | [] -> "unexpected " ^ found
            | l -> Printf.sprintf "expected %s, found %s" (String.concat " or " l) found)
      in
      fail t loc "%s" msg

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
      enter_if t c
  | "ifdef" | "ifndef" ->
      expect_tok t Parser.LPAREN "'(' after #ifdef";
      let name, _ = expect_ident t "an identifier" in
      expect_tok t Parser.RPAREN "')'";
      let defined = Env.find t.env name <> None || List.mem_assoc name t.config.builtins in
      enter_if t (if d = "ifdef" then defined else not defined)
  | "elseif" | "else" -> (
      match f.ctrl with
      | In_if :: rest ->
          (* the taken branch ends here: skip to #end *)
          f.ctrl <- rest;
          skip_to_end t
      | In_switch :: _ when d = "else" -> () (* falling through into #else *)
      | _ -> fail t loc "#%s without a matching #if" d)
  | "end" -> end_block t loc
  | "while" ->
      let cond_pos = f.pos in
      let c = Value.to_bool loc (parse t Parser.Incremental.paren_expr) in
      if c then f.ctrl <- In_while { cond_pos; count = 1 } :: f.ctrl else skip_to_end t
  | "for" -> for_loop t loc
  | "switch" -> switch t loc
  | "case" | "range" -> (
      match f.ctrl with
      | In_switch :: _ ->
          (* fall through: skip this clause's condition *)
          skip_condition t
      | _ -> fail t loc "#%s outside #switch" d)
  | "break" -> break t loc
  | "macro" -> define_macro t loc
  | "debug" | "warning" | "error" ->
      let s = parse t Parser.Incremental.string_arg in
      if d = "debug" then prerr_string s
      else if d = "warning" then Diag.warning loc s
      else fail t loc "#error: %s" s
  | "default" -> parse t Parser.Incremental.default_body
  | "fopen" | "fclose" | "read" | "write" ->
      fail t loc "#%s (file input/output) is not supported by camlray" d
  | _ -> fail t loc "unknown directive #%s" d

and enter_if t c =
  let f = top t in
  if c then f.ctrl <- In_if :: f.ctrl
  else
    let rec seek () =
      match skip_block t ~stop:[ "else"; "elseif" ] with
      | "else", _ -> f.ctrl <- In_if :: f.ctrl
      | "elseif", tok ->
          if Value.to_bool tok.loc (parse t Parser.Incremental.paren_expr) then
            f.ctrl <- In_if :: f.ctrl
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
  | (In_if | In_switch) :: rest -> f.ctrl <- rest
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
    f.ctrl <- In_for { var; stop; step; body_pos = f.pos; count = 1 } :: f.ctrl
  else skip_to_end t

and switch t loc =
  let v = Value.to_float loc (parse t Parser.Incremental.paren_expr) in
  let f = top t in
  let rec seek () =
    match skip_block t ~stop:[ "case"; "range"; "else" ] with
    | "case", tok ->
        let c = Value.to_float tok.loc (parse t Parser.Incremental.paren_expr) in
        if Float.abs (c -. v) <= 1e-10 then f.ctrl <- In_switch :: f.ctrl else seek ()
    | "range", tok ->
        expect_tok t Parser.LPAREN "'(' after #range";
        let lo = Value.to_float tok.loc (parse t Parser.Incremental.expr_then_comma) in
        let hi = Value.to_float tok.loc (parse t Parser.Incremental.expr_then_rparen) in
        if v >= lo && v <= hi then f.ctrl <- In_switch :: f.ctrl else seek ()
    | "else", _ -> f.ctrl <- In_switch :: f.ctrl
    | _ -> ()
  in
  (* the first clause starts right away: no tokens may stand before it *)
  seek ()

and break t loc =
  let f = top t in
  let rec unwind = function
    | In_switch :: rest -> f.ctrl <- rest; skip_to_end t
    | In_if :: rest -> f.ctrl <- rest; skip_to_end t; unwind rest
    | (In_while _ | In_for _) :: rest -> f.ctrl <- rest; skip_to_end t
    | [] -> fail t loc "#break outside #switch or a loop"
  in
  unwind f.ctrl

and declare t ~local loc =
  let name, nloc = expect_ident t "an identifier after #declare" in
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
          bind (Env.Array (new_array t loc))
      | _ -> bind (Env.Decl (rhs t)))

and rhs t =
  let d = parse t Parser.Incremental.declare_rhs in
  (* a layered texture: texture { ... } texture { ... }, the last on top *)
  let rec layers (d : Decl.t) =
    match (d, (raw_peek t).raw) with
    | Decl.Texture below, Tok Parser.TEXTURE -> (
        match parse t Parser.Incremental.declare_rhs with
        | Decl.Texture top -> layers (Decl.Texture (top @ below))
        | other -> other)
    | _ -> d
  in
  let d = layers d in
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
        if i >= n then fail t loc "too many initialisers (the array has %d elements)" n;
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
              let d, closed = parse t Parser.Incremental.macro_arg in
              if closed && rest <> [] then
                fail t loc "macro %s expects %d arguments, got %d" m.name (List.length ps)
                  (List.length acc + 1);
              if (not closed) && rest = [] then
                fail t loc "macro %s expects %d arguments, got more" m.name (List.length ps);
              go ((p, d) :: acc) rest
        in
        go [] ps
  in
  Env.push_scope t.env;
  List.iter (fun (p, d) -> Env.local t.env p (Env.Decl d)) args;
  t.frames <-
    { toks = m.body; pos = 0; kind = Macro_call (m.name, loc); file = m.file; ctrl = []; scoped = true }
    :: t.frames

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
  let scene_dir =
    let main = List.find (fun f -> f.kind = Main) t.frames in
    Filename.dirname main.file
  in
  let candidates =
    if not (Filename.is_relative name) then [ name ]
    else List.map (fun d -> Filename.concat d name) ("." :: scene_dir :: t.config.include_dirs)
  in
  match List.find_opt Sys.file_exists candidates with
  | None ->
      fail t tok.loc "cannot find include file %S (looked in %s)" name
        (String.concat ", " (List.sort_uniq compare (List.map Filename.dirname candidates)))
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
      let saved_version = Defaults.version () in
      ignore saved_version;
      t.frames <- { toks; pos = 0; kind = Include loc; file = path; ctrl = []; scoped = true } :: t.frames
