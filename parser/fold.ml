(* Arithmetic runs folded before the parser sees them (see fold.mli). *)
open Lexer
open Cursor

(* a run as read: a tree with each node's span, evaluated once complete *)
type e = { node : node; loc : Loc.t }

and node =
  | Num of float
  | Var of int  (** the i-th float name of a run kept to be read again (below) *)
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
  | FLOAT _ | FLOAT_ID _ | VECTOR _ | VECTOR_END _ | VECTOR_ID _ | STRING _ | STRING_ID _ | RPAREN | RBRACKET | GT
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
(* where a float name the run may read silently is read, as [ident]
   reads it (None: not a name the run may read silently); [value_into]:
   its value, if it is still a float *)
type how = Builtin of float | Version | Named of Env.cell

let how t name =
  if Hashtbl.length t.deprecated <> 0 && Hashtbl.mem t.deprecated name then None
  else
    match Cursor.builtin t name with
    | Some v -> Some (Builtin v)
    | None when String.equal name "version" -> Some Version
    | None -> Option.map (fun c -> Named c) (Env.lookup t.env name)

(* the value written into [a.(i)] (no option: a run read again in a
   loop reads its names at every turn); false when it is no float *)
let value_into h (a : float array) i =
  match h with
  | Builtin v -> Array.unsafe_set a i v; true
  | Version -> Array.unsafe_set a i (Defaults.version ()); true
  | Named c -> (
      match Env.binding c with
      | Env.Decl (Decl.Value (Value.Float f)) -> Array.unsafe_set a i f; true
      | _ -> false)

let silent_float t =
  match (raw_peek t).raw with
  | Ident name -> ( match how t name with Some h -> value_into h (Array.make 1 0.) 0 | None -> false)
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
  | PLUS ->
      (* the parser gives the operand itself, its span starting at the
         sign: a parenthesis does the same *)
      let e = unary st in
      { node = Paren e; loc = span loc e.loc }
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
let rec eval_with (values : float array) e =
  match e.node with
  | Num f -> Value.Float f
  | Var i -> Value.Float (Array.unsafe_get values i)
  | Bin (op, a, b) ->
      let a = eval_with values a in
      Value.binop e.loc op a (eval_with values b)
  | Neg a -> Value.neg e.loc (eval_with values a)
  | Paren a -> eval_with values a
  | Call (f, args) -> Value.call e.loc f (List.map (eval_with values) args)

let eval e = eval_with [||] e

(* A component of a vector read again, when it calls no function: its
   operands are floats, and Value.arith on floats is the float operation,
   with a warning before a division by zero (the order of the warnings,
   operands first, is kept) *)
type fe =
  | FNum of float
  | FVar of int
  | FAdd of fe * fe
  | FSub of fe * fe
  | FMul of fe * fe
  | FDiv of Loc.t * fe * fe
  | FNeg of fe

let rec plain e =
  match e.node with
  | Num f -> Some (FNum f)
  | Var i -> Some (FVar i)
  | Paren a -> plain a
  | Neg a -> Option.map (fun a -> FNeg a) (plain a)
  | Bin (op, a, b) -> (
      match (plain a, plain b) with
      | Some a, Some b -> (
          match op with
          | "+" -> Some (FAdd (a, b))
          | "-" -> Some (FSub (a, b))
          | "*" -> Some (FMul (a, b))
          | "/" -> Some (FDiv (e.loc, a, b))
          | _ -> None)
      | _ -> None)
  | Call _ -> None

let rec eval_float (values : float array) = function
  | FNum f -> f
  | FVar i -> Array.unsafe_get values i
  | FAdd (a, b) ->
      let x = eval_float values a in
      x +. eval_float values b
  | FSub (a, b) ->
      let x = eval_float values a in
      x -. eval_float values b
  | FMul (a, b) ->
      let x = eval_float values a in
      x *. eval_float values b
  | FDiv (loc, a, b) ->
      let x = eval_float values a in
      let y = eval_float values b in
      if y = 0. then Diag.warning loc "Divide by zero.";
      x /. y
  | FNeg a -> -.eval_float values a

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

(* Vectors read again. In a loop or a macro body the same tokens are read
   again and again: a vector run read there is kept, by position, as its
   tree with the float names it read left as names ([Var]), and read
   again from the tree when the same position comes up, if every one of
   those names is still a float read without a side effect (their values
   are looked up then), no token is pushed back, and the parser takes a
   vector there. The tokens are passed over (they count towards the
   token limit as if read), the arithmetic is done with the same
   functions, spans and order as a run read token by token, and the
   parser gets the same token: the scene and its errors are the same.
   Anything else (a name that has become a vector, a macro or a
   deprecated name; an error the parser would make) and the run is read
   token by token as before. Where each name is read (a built-in, or a
   symbol-table cell) is found once and kept while the table's
   generation stays ([how] above, [gen] below). *)

type plan = {
  len : int;  (** tokens in the run, its '<' and '>' included *)
  comps : e array;
  plain : fe option array;  (** the component in floats, if it calls no function *)
  span : Loc.t;
  names : string array;  (** the float names it reads, each once ([Var i] is [names.(i)]) *)
  mutable hows : how array;
  mutable gen : int;  (** the {!Env.generation} [hows] were found in; -1: none *)
  values : float array;  (** the names' values while the run is evaluated, reused *)
}

type Toks.memo += Plans of (int, plan) Hashtbl.t

(* where the same tokens are read again: a macro's body, an open loop *)
let read_again f =
  (match f.kind with Macro_call _ -> true | Main | Include _ -> false)
  || List.exists (function In_for _ | In_while _ -> true | In_if _ | In_switch _ -> false) f.ctrl

let plans f =
  match Toks.memo f.toks with
  | Plans h -> h
  | _ ->
      let h = Hashtbl.create 16 in
      Toks.set_memo f.toks (Plans h);
      h

(* After a vector run read token by token: keep it if its tokens are the
   top frame's, in order, the last one just read. *)
let keep t st cs span =
  match t.frames with
  | f :: _ when t.pending = [] && t.stop_at = None && read_again f ->
      let taken = Array.of_list (List.rev st.taken) in
      let len = Array.length taken in
      let p0 = f.pos - len in
      let raw i = Toks.get f.toks (p0 + i) in
      let rec same i = i >= len || ((raw i).loc == snd taken.(i) && same (i + 1)) in
      if p0 >= 0 && same 0 then begin
        let names = ref [] in
        for i = 0 to len - 1 do
          match (raw i).raw with Ident n -> names := ((raw i).loc, n) :: !names | _ -> ()
        done;
        let names_once = Array.of_list (List.sort_uniq String.compare (List.map snd !names)) in
        let index n =
          let rec go i = if String.equal names_once.(i) n then i else go (i + 1) in
          go 0
        in
        let rec named e =
          match e.node with
          | Num _ -> (
              match List.assq_opt e.loc !names with Some n -> { e with node = Var (index n) } | None -> e)
          | Var _ -> e
          | Bin (op, a, b) -> { e with node = Bin (op, named a, named b) }
          | Neg a -> { e with node = Neg (named a) }
          | Paren a -> { e with node = Paren (named a) }
          | Call (fn, args) -> { e with node = Call (fn, List.map named args) }
        in
        let comps = Array.of_list (List.map named cs) in
        let plan =
          { len; comps; plain = Array.map plain comps; span; names = names_once;
            hows = [||]; gen = -1; values = Array.make (Array.length names_once) 0. }
        in
        Hashtbl.replace (plans f) p0 plan
      end
  | _ -> ()

(* a ',' or '}' next: the expression before it is a whole parameter *)
let closes (tok : Lexer.token) = match tok.raw with Tok (COMMA | RBRACE) -> true | _ -> false

let replay t ~accepts (tok, (loc : Loc.t)) =
  match (tok : Parser.token) with
  | LT when t.pending = [] && t.stop_at = None -> (
      let f = top t in
      let p0 = f.pos - 1 in
      match Toks.memo f.toks with
      | Plans h -> (
          match Hashtbl.find_opt h p0 with
          | Some p
            when (Toks.get f.toks p0).loc == loc
                 && t.supplied + p.len - 1 <= t.config.limits.max_tokens -> (
              (* a ',' or '}' after the '>' ends the expression: if the
                 parser reads a parameter here, it is this vector *)
              let after = p0 + p.len in
              let ends =
                Toks.lexed f.toks after && closes (Toks.get f.toks after) && accepts (Parser.VECTOR_END [||])
              in
              if not (ends || accepts (Parser.VECTOR [||])) then None else
              let n = Array.length p.names in
              let gen = Env.generation t.env in
              let found =
                (p.gen = gen && Hashtbl.length t.deprecated = 0)
                ||
                let hows = Array.map (how t) p.names in
                Array.for_all Option.is_some hows
                && begin
                  p.hows <- Array.map Option.get hows;
                  p.gen <- (if Hashtbl.length t.deprecated = 0 then gen else -1);
                  true
                end
              in
              (* the values are read before any is used: a component
                 calls no declared function, which could replay this run *)
              let values = p.values in
              let rec resolve i = i >= n || (value_into (Array.unsafe_get p.hows i) values i && resolve (i + 1)) in
              if not (found && resolve 0) then None
              else begin
                f.pos <- p0 + p.len;
                t.supplied <- t.supplied + p.len - 1;
                let comp i =
                  match Array.unsafe_get p.plain i with
                  | Some f -> eval_float values f
                  | None ->
                      let e = Array.unsafe_get p.comps i in
                      Value.to_float e.loc (eval_with values e)
                in
                let v =
                  if Array.length p.comps = 3 then
                    let x = comp 0 in
                    let y = comp 1 in
                    [| x; y; comp 2 |]
                  else Array.init (Array.length p.comps) comp
                in
                Some ((if ends then Parser.VECTOR_END v else Parser.VECTOR v), p.span)
              end)
          | _ -> None)
      | _ -> None)
  | _ -> None

(* A ',' or '}' next in the frame (looked at, not read: its lexing
   happens where the parser would read it next anyway) ends the
   expression: a vector there is a whole parameter, if the parser reads
   one. *)
let ends_param t ~accepts =
  t.pending = [] && t.stop_at = None
  && closes (raw_peek t)
  && accepts (Parser.VECTOR_END [||])

let run_vector t ~next ~accepts first =
  t.pending <- first :: t.pending;
  let st = { t; next; taken = []; ahead = Unknown } in
  match vector st with
  | cs, loc ->
      let v = Array.of_list (List.map (fun e -> Value.to_float e.loc (eval e)) cs) in
      keep t st cs loc;
      (((if ends_param t ~accepts then Parser.VECTOR_END v else Parser.VECTOR v), loc), List.rev st.taken)
  | exception Bail -> give_back t st first

let run t ~next ~accepts ((tok, loc) as first) =
  match tok with
  | Parser.LT -> run_vector t ~next ~accepts first
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
