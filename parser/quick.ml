(* Plain expressions of directives evaluated without the parser (see
   quick.mli). *)
open Lexer
open Cursor

exception Bail

(* an expression as read, each node with the span the parser's action
   would be given ($loc: from its first token's start to its last
   token's end) *)
type e = { node : node; start : Lexing.position; stop : Lexing.position }

and node =
  | Val of Value.t  (** a literal or a name's value *)
  | Same of e  (** [( e )], [+ e]: the value of [e], a wider span *)
  | Bin of string * e * e
  | Neg of e
  | Not of e
  | Member of e * string
  | Call of string * e list
  | Fcall of Fn.t * e list
  | Vec of e list
  | Cond of e * e * e

(* the reader: tokens of the top frame from [i] on, never past what is
   lexed, never a directive or the frame's end *)
type st = { t : Cursor.t; toks : Toks.t; mutable i : int }

let tok st =
  if Toks.lexed st.toks st.i then Toks.get st.toks st.i else raise Bail

let peek st = match (tok st).raw with Tok x -> x | Ident _ | Directive _ | Eof -> Parser.EOF

let take st =
  let x = tok st in
  st.i <- st.i + 1;
  x

let expect st (x : Parser.token) =
  let k = take st in
  match k.raw with Tok y when y = x -> k.loc | _ -> raise Bail

let node start stop node = { node; start; stop }

(* A name as [Supplier.ident] reads it, when reading it has no effect of
   its own: a built-in, [version], a declared float, vector, string or
   function, not deprecated. *)
type named = Value of Value.t | Function of Fn.t

let name t n =
  match Cursor.builtin t n with
  | Some v -> Value (Value.Float v)
  | None when String.equal n "version" -> Value (Value.Float (Defaults.version ()))
  | None -> (
      if Hashtbl.length t.deprecated <> 0 && Hashtbl.mem t.deprecated n then raise Bail;
      match Env.find t.env n with
      | Some (Env.Decl (Decl.Value v)) -> Value v
      | Some (Env.Decl (Decl.Function f)) -> Function f
      | _ -> raise Bail)

(* The grammar's expr / logic / rel / add / mul / unary / postfix /
   primary (grammar_lang.mly), by recursive descent: left-associative
   where its rules are left-recursive, each operator where the grammar
   takes it. A '<' is a vector where a primary starts, a comparison after
   an operand. *)
let rec expr st =
  let c = logic st in
  match peek st with
  | QUESTION ->
      st.i <- st.i + 1;
      let a = expr st in
      ignore (expect st Parser.COLON);
      let b = expr st in
      node c.start b.stop (Cond (c, a, b))
  | _ -> c

and left ops next st =
  let rec more l =
    match ops (peek st) with
    | Some op ->
        st.i <- st.i + 1;
        let r = next st in
        more (node l.start r.stop (Bin (op, l, r)))
    | None -> l
  in
  more (next st)

and logic st = left (function Parser.AND -> Some "&" | OR -> Some "|" | _ -> None) rel st

and rel st =
  left
    (function
      | Parser.LT -> Some "<" | LE -> Some "<=" | GT -> Some ">" | GE -> Some ">=" | EQ -> Some "="
      | NE -> Some "!=" | _ -> None)
    add st

and add st = left (function Parser.PLUS -> Some "+" | MINUS -> Some "-" | _ -> None) mul st
and mul st = left (function Parser.STAR -> Some "*" | SLASH -> Some "/" | _ -> None) unary st

and unary st =
  let k = tok st in
  match k.raw with
  | Tok Parser.MINUS ->
      st.i <- st.i + 1;
      let e = unary st in
      node k.loc.start e.stop (Neg e)
  | Tok Parser.PLUS ->
      st.i <- st.i + 1;
      let e = unary st in
      node k.loc.start e.stop (Same e)
  | Tok Parser.BANG ->
      st.i <- st.i + 1;
      let e = unary st in
      node k.loc.start e.stop (Not e)
  | _ -> postfix st (primary st)

and postfix st e =
  let k = tok st in
  match k.raw with
  | Tok (Parser.MEMBER m) ->
      st.i <- st.i + 1;
      postfix st (node e.start k.loc.stop (Member (e, m)))
  | _ -> e

and primary st =
  let k = take st in
  let l = k.loc in
  match k.raw with
  | Tok (Parser.FLOAT f) -> node l.start l.stop (Val (Value.Float f))
  | Tok (Parser.VECTOR v) -> node l.start l.stop (Val (Value.Vector v))
  | Tok (Parser.STRING s) -> node l.start l.stop (Val (Value.String s))
  | Ident n -> (
      match name st.t n with
      | Value v -> node l.start l.stop (Val v)
      | Function f ->
          ignore (expect st Parser.LPAREN);
          let args, stop = args st in
          node l.start stop (Fcall (f, args)))
  | Tok Parser.LPAREN ->
      let e = expr st in
      let stop = expect st Parser.RPAREN in
      node l.start stop.stop (Same e)
  | Tok (Parser.FUNC f) ->
      ignore (expect st Parser.LPAREN);
      let args, stop = args st in
      node l.start stop (Call (f, args))
  | Tok Parser.LT ->
      (* 2 to 5 components, each an add, separated by commas, a trailing
         comma allowed; anything else (components without commas, other
         counts) is the parser's *)
      let rec items acc =
        let c = add st in
        let k = take st in
        match k.raw with
        | Tok Parser.GT -> (c :: acc, k.loc.stop)
        | Tok Parser.COMMA when peek st = Parser.GT -> (c :: acc, (take st).loc.stop)
        | Tok Parser.COMMA -> items (c :: acc)
        | _ -> raise Bail
      in
      let cs, stop = items [] in
      let n = List.length cs in
      if n < 2 || n > 5 then raise Bail;
      node l.start stop (Vec (List.rev cs))
  | _ -> raise Bail

(* separated_list(COMMA, expr) RPAREN: the arguments and the ')''s end *)
and args st =
  match peek st with
  | RPAREN -> ([], (take st).loc.stop)
  | _ ->
      let rec go acc =
        let a = expr st in
        let k = take st in
        match k.raw with
        | Tok Parser.COMMA -> go (a :: acc)
        | Tok Parser.RPAREN -> (List.rev (a :: acc), k.loc.stop)
        | _ -> raise Bail
      in
      go []

(* The parser's actions, in its order: operands first, left to right,
   each node with its own span. *)
let rec eval e =
  let l () = Loc.make e.start e.stop in
  match e.node with
  | Val v -> v
  | Same a -> eval a
  | Bin (op, a, b) ->
      let a = eval a in
      let b = eval b in
      Value.binop (l ()) op a b
  | Neg a -> Value.neg (l ()) (eval a)
  | Not a -> Value.not_ (l ()) (eval a)
  | Member (a, m) -> Value.dot_member (l ()) (eval a) m
  | Call (f, args) -> Value.call (l ()) f (eval_list args)
  | Fcall (f, args) -> Gram.call_function (l ()) f (eval_list args)
  | Vec cs -> Gram.vector_literal (l ()) (eval_list cs)
  | Cond (c, a, b) ->
      let cv = eval c in
      let av = eval a in
      let bv = eval b in
      if Value.to_bool (Loc.make c.start c.stop) cv then av else bv

and eval_list = function
  | [] -> []
  | x :: rest ->
      let v = eval x in
      v :: eval_list rest

(* ['(' expr] when [paren], else [expr], then a token [close] takes (the
   ')' for [paren]): the value and that token, the phrase passed over;
   [None], nothing read, when the phrase is not one this module reads. *)
let phrase t ~paren ~(close : Parser.token -> bool) =
  if not (t.config.quick && t.pending = [] && t.stop_at = None) then None
  else
    let f = top t in
    let st = { t; toks = f.toks; i = f.pos } in
    match
      if paren then ignore (expect st Parser.LPAREN);
      let e = expr st in
      let k = take st in
      match k.raw with Tok x when close x -> (e, k, x) | _ -> raise Bail
    with
    | exception Bail -> None
    | e, k, x ->
        let n = st.i - f.pos in
        if t.supplied + n > t.config.limits.max_tokens then None
        else begin
          (* as the parser would leave them: the phrase read, its last
             token the last given, the one-shot settings of a sub-parse
             spent *)
          f.pos <- st.i;
          t.supplied <- t.supplied + n;
          t.last <- k.loc;
          t.optional_sep <- None;
          t.semi_probe <- None;
          Some (eval e, x)
        end

let paren_expr t =
  match phrase t ~paren:true ~close:(function Parser.RPAREN -> true | _ -> false) with
  | Some (v, _) -> v
  | None -> Cursor.parse t Parser.Incremental.paren_expr

let expr_then_comma t =
  match phrase t ~paren:false ~close:(function Parser.COMMA -> true | _ -> false) with
  | Some (v, _) -> v
  | None -> Cursor.parse t Parser.Incremental.expr_then_comma

let expr_then_rparen t =
  match phrase t ~paren:false ~close:(function Parser.RPAREN -> true | _ -> false) with
  | Some (v, _) -> v
  | None -> Cursor.parse t Parser.Incremental.expr_then_rparen

let expr_then_rbracket t =
  match phrase t ~paren:false ~close:(function Parser.RBRACKET -> true | _ -> false) with
  | Some (v, _) -> v
  | None -> Cursor.parse t Parser.Incremental.expr_then_rbracket

let expr_then_sep t =
  match phrase t ~paren:false ~close:(function Parser.COMMA | RPAREN -> true | _ -> false) with
  | Some (v, x) -> (v, x = Parser.COMMA)
  | None -> Cursor.parse t Parser.Incremental.expr_then_sep

let macro_arg t =
  match phrase t ~paren:false ~close:(function Parser.COMMA | RPAREN -> true | _ -> false) with
  | Some (v, x) -> (Decl.Value v, x = Parser.RPAREN)
  | None -> Cursor.parse t Parser.Incremental.macro_arg

let declare_value t =
  match phrase t ~paren:false ~close:(function Parser.SEMI -> true | _ -> false) with
  | Some (v, _) -> Some (Decl.Value v)
  | None -> None
