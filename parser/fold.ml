(* Arithmetic runs folded before the parser sees them (see fold.mli). *)
open Lexer
open Cursor

(* a run as read: a tree with each node's span, evaluated once complete *)
type e = { node : node; loc : Loc.t }

and node =
  | Num of float
  | Bin of string * e * e
  | Neg of e
  | Paren of e
  | Call of string * e list

exception Bail

(* What comes next, without reading it: a token, a name (read and typed
   only when taken), or something that may add tokens or is not the end
   of the expression (a directive, the end of an included file or a macro
   body). *)
type ahead = Plain of Parser.token | Name | Other | Unknown

type st = {
  t : Cursor.t;
  next : Cursor.t -> Parser.token * Loc.t;
  mutable taken : (Parser.token * Loc.t) list;  (** read so far, last first *)
  mutable ahead : ahead;  (** the next token, [Unknown] until peeked *)
}

(* Functions of floats to a float, with no state (not rand, seed). *)
let pure = function
  | "sin" | "cos" | "tan" | "asin" | "acos" | "atan" | "atan2" | "sinh" | "cosh" | "tanh"
  | "asinh" | "acosh" | "atanh" | "sqrt" | "sqr" | "pow" | "exp" | "log" | "ln" | "abs"
  | "floor" | "ceil" | "int" | "mod" | "div" | "radians" | "degrees" | "bitwise_and"
  | "bitwise_or" | "bitwise_xor" | "min" | "max" | "select" ->
      true
  | _ -> false

let starts (tok : Parser.token) =
  match tok with
  | FLOAT _ | FLOAT_ID _ | LPAREN | MINUS | PLUS -> true
  | FUNC f -> pure f
  | _ -> false

(* a lone number is no run: most numbers are followed by no operator *)
let operator_next t =
  let op (x : Parser.token) = match x with PLUS | MINUS | STAR | SLASH -> true | _ -> false in
  match t.pending with
  | (x, _) :: _ -> op x
  | [] -> ( match (raw_peek t).raw with Tok x -> op x | _ -> false)

(* After these a '<' is a comparison, not the start of a vector *)
let operand_end (tok : Parser.token) =
  match tok with
  | FLOAT _ | FLOAT_ID _ | VECTOR _ | VECTOR_ID _ | STRING _ | STRING_ID _ | RPAREN | RBRACKET | GT
  | MEMBER _ | UNDEFINED_ID _ | FUNCTION_ID _ | FUNCTION_LIT _ ->
      true
  | _ -> false

let may_start t last tok =
  match tok with
  | Parser.LT -> (
      (* a vector is a whole primary: whatever comes before it (an
         operator, a keyword, rgb) takes it as it would the literal *)
      match last with None -> true | Some (l, _) -> not (operand_end l))
  | _ -> (
      (match last with
      | None -> (* #if (...) wants its parenthesis *) tok <> Parser.LPAREN
      | Some ((COMMA | LT | LPAREN | LBRACKET | LBRACE : Parser.token), _) -> true
      | Some _ -> false)
      && match tok with FLOAT _ | FLOAT_ID _ -> operator_next t | _ -> starts tok)

let peek st =
  match st.ahead with
  | Unknown ->
      let a =
        match st.t.pending with
        | (x, _) :: _ -> Plain x
        | [] when st.t.stop_at <> None -> Other
        | [] -> (
            match (raw_peek st.t).raw with
            | Tok x -> Plain x
            | Eof when (top st.t).kind = Main -> Plain Parser.EOF
            | Ident _ -> Name
            | Eof | Directive _ -> Other)
      in
      st.ahead <- a;
      a
  | a -> a

(* The name ahead is a float read without a side effect: a built-in or a
   declared float, not deprecated (no warning). Anything else (a macro,
   an array element, a spline) is read by the parser, so that its effects
   and errors come where they would: everything the run reads is silent,
   and its arithmetic is done once, when it is whole, in the parser's
   order. *)
let silent_float t =
  match (raw_peek t).raw with
  | Ident name ->
      (Hashtbl.length t.deprecated = 0 || not (Hashtbl.mem t.deprecated name))
      && (Cursor.builtin t name <> None || String.equal name "version"
         || match Env.find t.env name with Some (Env.Decl (Decl.Value (Value.Float _))) -> true | _ -> false)
  | _ -> false

let take st =
  let x = st.next st.t in
  st.taken <- x :: st.taken;
  st.ahead <- Unknown;
  x

let span (a : Loc.t) (b : Loc.t) = Loc.make a.start b.stop

let expect st (tok : Parser.token) =
  match peek st with
  | Plain x when x = tok -> snd (take st)
  | _ -> raise Bail

(* The grammar's add / mul / unary / primary, greedy as it is: a run ends
   where the next token cannot continue it. *)
let additive : Parser.token -> string option = function PLUS -> Some "+" | MINUS -> Some "-" | _ -> None
let multiplicative : Parser.token -> string option = function STAR -> Some "*" | SLASH -> Some "/" | _ -> None

(* operands of [next] joined by the operators [op] names, left to right *)
let rec binary op next st =
  let rec more l =
    match peek st with
    | Plain tok -> (
        match op tok with
        | Some name ->
            ignore (take st);
            let r = next st in
            more { node = Bin (name, l, r); loc = span l.loc r.loc }
        | None -> l)
    | Name | Other | Unknown -> l
  in
  more (next st)

and add st = binary additive mul st
and mul st = binary multiplicative unary st

and unary st =
  (match peek st with
  | Plain (FLOAT _ | FLOAT_ID _ | LPAREN | MINUS | PLUS | FUNC _) -> ()
  | Name when silent_float st.t -> ()
  | Plain _ | Name | Other | Unknown -> raise Bail);
  let tok, loc = take st in
  match tok with
  | MINUS ->
      let e = unary st in
      { node = Neg e; loc = span loc e.loc }
  | PLUS -> unary st
  | FLOAT f | FLOAT_ID f -> primary_end st { node = Num f; loc }
  | LPAREN ->
      let e = add st in
      let stop = expect st RPAREN in
      primary_end st { node = Paren e; loc = span loc stop }
  | FUNC f when pure f ->
      ignore (expect st LPAREN);
      let args =
        match peek st with
        | Plain RPAREN -> []
        | _ ->
            let rec go acc =
              let a = add st in
              match peek st with
              | Plain COMMA -> ignore (take st); go (a :: acc)
              | _ -> List.rev (a :: acc)
            in
            go []
      in
      let stop = expect st RPAREN in
      primary_end st { node = Call (f, args); loc = span loc stop }
  | _ -> raise Bail

(* a member ('.x') would bind to the primary alone; a name (a macro) or
   a directive after it may continue the expression *)
and primary_end st e =
  match peek st with
  | Plain (MEMBER _) | Name | Other | Unknown -> raise Bail
  | Plain _ -> e

(* In the order the parser's actions would run: left to right, inner
   first, each with the span the parser would give it. *)
let rec eval e =
  match e.node with
  | Num f -> Value.Float f
  | Bin (op, a, b) ->
      let a = eval a in
      Value.binop e.loc op a (eval b)
  | Neg a -> Value.neg e.loc (eval a)
  | Paren a -> eval a
  | Call (f, args) -> Value.call e.loc f (List.map eval args)

(* < run, run [, run [, run]] >: 2 to 5 components, each a run ending at
   the comma or the '>' (no trailing comma, no components written without
   commas: those go to the parser) *)
let vector st =
  let _, start = take st in
  let rec items acc =
    let e = add st in
    match peek st with
    | Plain COMMA -> ignore (take st); items (e :: acc)
    | Plain GT ->
        let _, stop = take st in
        (List.rev (e :: acc), stop)
    | _ -> raise Bail
  in
  let cs, stop = items [] in
  let n = List.length cs in
  if n < 2 || n > 5 then raise Bail;
  (cs, span start stop)

let give_back t st first =
  match List.rev st.taken with
  | [] -> t.pending <- List.tl t.pending; (first, [])
  | x :: rest -> t.pending <- rest @ t.pending; (x, [])

let run_vector t ~next first =
  t.pending <- first :: t.pending;
  let st = { t; next; taken = []; ahead = Unknown } in
  match vector st with
  | cs, loc ->
      let v = Array.of_list (List.map (fun e -> Value.to_float e.loc (eval e)) cs) in
      ((Parser.VECTOR v, loc), List.rev st.taken)
  | exception Bail -> give_back t st first

let run t ~next ((tok, loc) as first) =
  match tok with
  | Parser.LT -> run_vector t ~next first
  | Parser.LPAREN | MINUS | PLUS | FUNC _ | FLOAT _ | FLOAT_ID _ -> (
      (* [first] is read: put it back for the descent to take again *)
      t.pending <- first :: t.pending;
      let st = { t; next; taken = []; ahead = Unknown } in
      match add st with
      | e -> (
          match st.taken with
          | [ _ ] -> (first, [])
          | taken -> (
              let loc = span loc e.loc in
              let tok =
                match eval e with
                | Value.Float f -> Parser.FLOAT f
                | Value.Vector a -> Parser.VECTOR a
                | Value.String s -> Parser.STRING s
              in
              ((tok, loc), List.rev taken)))
      | exception Bail -> give_back t st first)
  | _ -> (first, [])
