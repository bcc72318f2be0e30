(* Conditionals, loops and #switch: the open structures of a frame and
   the skipping of untaken branches. *)
open Lexer
open Cursor

let rec enter_if t loc c =
  let f = top t in
  if c then f.ctrl <- In_if loc :: f.ctrl
  else
    let rec seek () =
      match skip_block t ~stop:[ "else"; "elseif" ] with
      | "else", _ -> f.ctrl <- In_if loc :: f.ctrl
      | "elseif", tok ->
          if Value.to_bool tok.loc (Quick.paren_expr t) then
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
    match (Toks.get f.toks f.pos).raw with
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
      let cond = Value.to_bool loc (Quick.paren_expr t) in
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
  let start = Value.to_float loc (Quick.expr_then_comma t) in
  let stop, closed = Quick.macro_arg t in
  let num d = match d with Decl.Value v -> Value.to_float loc v | _ -> fail t loc "#for bounds must be floats" in
  let stop = num stop in
  let step = if closed then 1. else Value.to_float loc (Quick.expr_then_rparen t) in
  if step = 0. then fail t loc "#for step cannot be 0";
  Env.declare t.env var (Env.Decl (Decl.Value (Value.Float start)));
  let f = top t in
  if (step > 0. && start <= stop) || (step < 0. && start >= stop) then
    f.ctrl <- In_for { var; stop; step; body_pos = f.pos; count = 1; floc = loc } :: f.ctrl
  else skip_to_end t

and switch t loc =
  let v = Value.to_float loc (Quick.paren_expr t) in
  let f = top t in
  let rec seek () =
    match skip_block t ~stop:[ "case"; "range"; "else" ] with
    | "case", tok ->
        let c = Value.to_float tok.loc (Quick.paren_expr t) in
        if Float.abs (c -. v) <= 1e-10 then f.ctrl <- In_switch loc :: f.ctrl else seek ()
    | "range", tok ->
        expect_tok t Parser.LPAREN "'(' after #range";
        let lo = Value.to_float tok.loc (Quick.expr_then_comma t) in
        let hi = Value.to_float tok.loc (Quick.expr_then_rparen t) in
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

