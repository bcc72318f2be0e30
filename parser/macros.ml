(* Macros (definition, call with arguments, by-reference identifiers)
   and #include: the directives that push a new frame of tokens. *)
open Lexer
open Cursor

let define t loc =
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
  let eof = { raw = Eof; loc = (Toks.get f.toks body_end).loc } in
  let body = Toks.of_array (Array.append (Toks.sub f.toks body_start (body_end - body_start)) [| eof |]) in
  Env.declare t.env name (Env.Macro { name; params = ps; body; file = f.file; mloc = loc })

let rec call t (m : Env.macro) loc =
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
              let arg, closed = argument t in
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
      scoped = true; byref }
    :: t.frames

(* One macro argument and whether it closed the list. A bare declared
   identifier (NAME followed by ',' or ')') is passed by reference, as in
   POV-Ray: arrays as themselves, other values copied back at the end. *)
(* NAME[i]... followed by ',' or ')': an element passed by reference. *)
and element_ref t f name a =
  let at i = if Toks.mem f.toks i then (Toks.get f.toks i).raw else Eof in
  let rec close i depth =
    match at i with
    | Tok Parser.LBRACKET -> close (i + 1) (depth + 1)
    | Tok Parser.RBRACKET ->
        if depth = 1 then (match at (i + 1) with Tok Parser.LBRACKET -> close (i + 1) 0 | _ -> Some (i + 1))
        else close (i + 1) (depth - 1)
    | Eof | Directive _ -> None
    | _ when depth = 0 -> None
    | _ -> close (i + 1) depth
  in
  match close (f.pos + 1) 0 with
  | Some e when (match at e with Tok (Parser.COMMA | Parser.RPAREN) -> true | _ -> false) ->
      let nloc = (Toks.get f.toks f.pos).loc in
      f.pos <- f.pos + 1;
      let rec go a =
        ignore (raw_next t);
        let i = Value.to_int nloc (Quick.expr_then_rbracket t) in
        if i < 0 || i >= Array.length a then
          fail t nloc "index %d is outside the array %s (size %d)" i name (Array.length a);
        match ((raw_peek t).raw, a.(i)) with
        | Tok Parser.LBRACKET, Some (Env.Array a') -> go a'
        | Tok Parser.LBRACKET, _ -> fail t nloc "%s has fewer dimensions than indices" name
        | _, None -> fail t nloc "element %s[%d] has not been set" name i
        | _, Some b -> (b, Element (a, i))
      in
      let b, target = go a in
      let sep = raw_next t in
      Some ((b, Some target), sep.raw = Tok Parser.RPAREN)
  | _ -> None

and argument t =
  let f = top t in
  let bare =
    match (Toks.get f.toks f.pos).raw with
    | Ident n when t.pending = [] && Toks.mem f.toks (f.pos + 1) -> (
        match ((Toks.get f.toks (f.pos + 1)).raw, Env.find t.env n) with
        | Tok ((Parser.COMMA | Parser.RPAREN) as sep), Some ((Env.Array _ | Env.Decl _) as b) ->
            f.pos <- f.pos + 2;
            Some ((b, Some (Name n)), sep = Parser.RPAREN)
        | Tok Parser.LBRACKET, Some (Env.Array a) -> element_ref t f n a
        | _ -> None)
    | _ -> None
  in
  match bare with
  | Some x -> x
  | None ->
      (* POV-Ray's commas between arguments are optional: M(A -y, B) is
         M(A, -y, B) when A is an object (its incdemo/shapes.pov) *)
      t.optional_sep <- Some Parser.COMMA;
      let d, closed = Quick.macro_arg t in
      ((Env.Decl d, None), closed)
let include_file t loc =
  let tok = raw_next t in
  let name =
    match tok.raw with
    | Tok (Parser.STRING s) -> s
    | Ident _ | Tok (Parser.FUNC _) ->
        (top t).pos <- (top t).pos - 1;
        Cursor.parse t Parser.Incremental.string_arg
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
      allowed t tok.loc path;
      let abs = if Filename.is_relative path then Filename.concat (Sys.getcwd ()) path else path in
      if List.exists (fun f -> f.file = path && f.kind <> Main) t.frames then
        fail t tok.loc "include cycle: %S includes itself" name;
      let text =
        try In_channel.with_open_bin path In_channel.input_all
        with Sys_error e -> fail t tok.loc "cannot read %s: %s" path e
      in
      let toks = Toks.of_text ~file:path text in
      if not (List.mem abs t.files) then t.files <- abs :: t.files;
      Env.push_scope t.env;
      t.frames <-
        { toks; pos = 0; kind = Include loc; file = path; ctrl = []; scoped = true;
          byref = [] }
        :: t.frames

