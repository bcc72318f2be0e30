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
type st = {
  t : Cursor.t;
  toks : Toks.t;
  mutable i : int;
  mutable cur : Lexer.token;  (** token [i], when [at] = [i] *)
  mutable at : int;
}

let tok st =
  if st.at = st.i then st.cur
  else if Toks.lexed st.toks st.i then begin
    let k = Toks.get st.toks st.i in
    st.cur <- k;
    st.at <- st.i;
    k
  end
  else raise Bail

let peek st = match (tok st).raw with Tok x -> x | Ident _ | Directive _ | Eof -> Parser.EOF

let take st =
  let x = tok st in
  st.i <- st.i + 1;
  x

let is_lparen : Parser.token -> bool = function LPAREN -> true | _ -> false
let is_rparen : Parser.token -> bool = function RPAREN -> true | _ -> false
let is_colon : Parser.token -> bool = function COLON -> true | _ -> false

let expect st is =
  let k = take st in
  match k.raw with Tok y when is y -> k.loc | _ -> raise Bail

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

(* the operators of each level of the grammar, by name ("": none) *)
let logic_op : Parser.token -> string = function AND -> "&" | OR -> "|" | _ -> ""

let rel_op : Parser.token -> string = function
  | LT -> "<" | LE -> "<=" | GT -> ">" | GE -> ">=" | EQ -> "=" | NE -> "!=" | _ -> ""

let add_op : Parser.token -> string = function PLUS -> "+" | MINUS -> "-" | _ -> ""
let mul_op : Parser.token -> string = function STAR -> "*" | SLASH -> "/" | _ -> ""

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
      ignore (expect st is_colon);
      let b = expr st in
      node c.start b.stop (Cond (c, a, b))
  | _ -> c

(* operands of [next] joined by the operators [ops] names, left to right *)
and more ops next st l =
  match ops (peek st) with
  | "" -> l
  | op ->
      st.i <- st.i + 1;
      let r = next st in
      more ops next st (node l.start r.stop (Bin (op, l, r)))

and logic st = more logic_op rel st (rel st)
and rel st = more rel_op add st (add st)
and add st = more add_op mul st (mul st)
and mul st = more mul_op unary st (unary st)

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
          ignore (expect st is_lparen);
          let args, stop = args st in
          node l.start stop (Fcall (f, args)))
  | Tok Parser.LPAREN ->
      let e = expr st in
      let stop = expect st is_rparen in
      node l.start stop.stop (Same e)
  | Tok (Parser.FUNC f) ->
      ignore (expect st is_lparen);
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
        | Tok Parser.COMMA when (match peek st with GT -> true | _ -> false) -> (c :: acc, (take st).loc.stop)
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
    let st = { t; toks = f.toks; i = f.pos; cur = Lexer.{ raw = Eof; loc = Loc.none }; at = -1 } in
    match
      if paren then ignore (expect st is_lparen);
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

(* a phrase read here, or the grammar's [entry] reading it *)
let or_parse t ~paren ~close entry =
  match phrase t ~paren ~close with Some (v, _) -> v | None -> Cursor.parse t entry

let paren_expr t =
  or_parse t ~paren:true ~close:(function Parser.RPAREN -> true | _ -> false) Parser.Incremental.paren_expr

let expr_then_comma t =
  or_parse t ~paren:false ~close:(function Parser.COMMA -> true | _ -> false) Parser.Incremental.expr_then_comma

let expr_then_rparen t =
  or_parse t ~paren:false ~close:(function Parser.RPAREN -> true | _ -> false) Parser.Incremental.expr_then_rparen

let expr_then_rbracket t =
  or_parse t ~paren:false ~close:(function Parser.RBRACKET -> true | _ -> false)
    Parser.Incremental.expr_then_rbracket

let expr_then_sep t =
  match phrase t ~paren:false ~close:(function Parser.COMMA | RPAREN -> true | _ -> false) with
  | Some (v, x) -> (v, match x with Parser.COMMA -> true | _ -> false)
  | None -> Cursor.parse t Parser.Incremental.expr_then_sep

let macro_arg t =
  match phrase t ~paren:false ~close:(function Parser.COMMA | RPAREN -> true | _ -> false) with
  | Some (v, x) -> (Decl.Value v, match x with Parser.RPAREN -> true | _ -> false)
  | None -> Cursor.parse t Parser.Incremental.macro_arg

let declare_value t =
  match phrase t ~paren:false ~close:(function Parser.SEMI -> true | _ -> false) with
  | Some (v, _) -> Some (Decl.Value v)
  | None -> None
