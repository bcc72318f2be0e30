(* spline { ... } declarations and spline calls S(t [, kind]). *)
open Lexer
open Cursor

(* Where the value starting at the current position ends: at a ',' or
   '}' at depth 0, or where an operand directly follows a complete operand
   (POV-Ray lets a spline value be followed by the next parameter without
   a comma). [None] when the value runs past this frame. *)
let value_end t =
  let f = top t in
  let rec go i depth prev =
    if not (Toks.mem f.toks i) then None
    else
      let starts = function
        | Tok (Parser.FLOAT _ | Parser.LT | Parser.VECTOR _ | Parser.FUNC _ | Parser.STRING _) | Ident _ -> true
        | _ -> false
      in
      match (Toks.get f.toks i).raw with
      | Eof | Directive _ -> None
      | (Tok Parser.COMMA | Tok Parser.RBRACE) as r when depth = 0 -> Some (i, r)
      | r when depth = 0 && prev && starts r -> Some (i, r)
      | Tok Parser.LT when not prev -> go (i + 1) (depth + 1) false
      | Tok Parser.GT when depth > 0 -> go (i + 1) (depth - 1) true
      | Tok (Parser.LPAREN | Parser.LBRACKET) -> go (i + 1) (depth + 1) false
      | Tok (Parser.RPAREN | Parser.RBRACKET) -> go (i + 1) (max 0 (depth - 1)) true
      | Tok (Parser.FLOAT _ | Parser.VECTOR _ | Parser.STRING _ | Parser.MEMBER _) | Ident _ -> go (i + 1) depth true
      | _ -> go (i + 1) depth false
  in
  go f.pos 0 false

let value t loc =
  let v =
    match value_end t with
    | Some (_, Tok Parser.COMMA) -> parse t Parser.Incremental.expr_then_comma
    | Some (i, _) ->
        t.stop_at <- Some (top t, i);
        parse t Parser.Incremental.expr_then_semi
    | None -> fail t loc "end this spline value with ','"
  in
  match v with
  | Value.Float x -> (Array.make 5 x, 2)
  | Value.Vector a -> (a, Array.length a)
  | Value.String _ -> fail t loc "a spline's values are floats or vectors"

let read t loc =
  expect_tok t Parser.LBRACE "'{' after spline";
  let rec go s =
    let tok = raw_peek t in
    match tok.raw with
    | Tok Parser.RBRACE ->
        ignore (raw_next t);
        if Spline.length s = 0 then fail t loc "this spline has no points";
        s
    | Ident name when Spline.kind_of_name name <> None ->
        ignore (raw_next t);
        go (Spline.with_kind s (Option.get (Spline.kind_of_name name)))
    | Ident name when (match Env.find t.env name with Some (Env.Decl (Decl.Spline _)) -> true | _ -> false) -> (
        ignore (raw_next t);
        match Env.find t.env name with
        | Some (Env.Decl (Decl.Spline s')) -> go s'
        | _ -> assert false)
    | _ ->
        let p = Value.to_float tok.loc (parse t Parser.Incremental.expr_then_comma) in
        let v, terms = value t tok.loc in
        (match (raw_peek t).raw with Tok Parser.COMMA -> ignore (raw_next t) | _ -> ());
        go (Spline.add s p ~terms v)
  in
  go (Spline.empty Spline.Linear)

let call t s loc =
  expect_tok t Parser.LPAREN "'(' after the spline's name";
  let d, closed = parse t Parser.Incremental.macro_arg in
  let p = match d with Decl.Value v -> Value.to_float loc v | d -> fail t loc "expected a float, found %s" (Decl.kind_name d) in
  let kind =
    if closed then None
    else
      let name, nloc = expect_ident t "a spline kind (linear_spline, ...)" in
      match Spline.kind_of_name name with
      | Some k -> expect_tok t Parser.RPAREN "')'"; Some k
      | None -> fail t nloc "expected linear_spline, quadratic_spline, cubic_spline or natural_spline, found %s" name
  in
  Spline.eval ?kind s p
