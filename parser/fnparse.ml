(* The body parser of user-defined functions: recursive descent over the
   raw tokens of a function { ... } body, producing Fn closures.
   Constants fold at compile time. *)
open Lexer

type resolved = Const of float | Vec of float array | Func of Fn.t | Unknown

(* A compiled sub-expression: a constant, or code over the slots. *)
type c = K of float | C of (float array -> float)

let run = function K k -> fun _ -> k | C f -> f

let lift1 g = function K a -> K (g a) | C f -> C (fun s -> g (f s))

let lift2 g a b =
  match (a, b) with
  | K x, K y -> K (g x y)
  | K x, C f -> C (fun s -> g x (f s))
  | C f, K y -> C (fun s -> g (f s) y)
  | C f, C h -> C (fun s -> g (f s) (h s))

let deg = 180. /. Float.pi
let b2f b = if b then 1. else 0.

let unary_builtins =
  [ ("sin", Float.sin); ("cos", Float.cos); ("tan", Float.tan); ("asin", Float.asin);
    ("acos", Float.acos); ("atan", Float.atan); ("sinh", Float.sinh); ("cosh", Float.cosh);
    ("tanh", Float.tanh);
    ("asinh", fun x -> Float.log (x +. Float.sqrt ((x *. x) +. 1.)));
    ("acosh", fun x -> Float.log (x +. Float.sqrt ((x *. x) -. 1.)));
    ("atanh", fun x -> 0.5 *. Float.log ((1. +. x) /. (1. -. x)));
    ("sqrt", Float.sqrt); ("exp", Float.exp); ("ln", Float.log);
    ("log", Float.log10); ("abs", Float.abs); ("floor", Float.floor); ("ceil", Float.ceil);
    ("int", Float.trunc); ("radians", fun a -> a /. deg); ("degrees", fun a -> a *. deg) ]

let binary_builtins =
  [ ("atan2", Float.atan2); ("pow", Float.pow); ("mod", Float.rem);
    ("div", fun a b -> Float.trunc (a /. b)) ]

(* The name a keyword token stands for when it names a parameter. *)
let word = function
  | Tok (Parser.VECTOR [| 1.; 0.; 0. |]) -> Some "x"
  | Tok (Parser.VECTOR [| 0.; 1.; 0. |]) -> Some "y"
  | Tok (Parser.VECTOR [| 0.; 0.; 1. |]) -> Some "z"
  | Tok (Parser.VECTOR [| 0.; 0.; 0.; 1. |]) -> Some "t"
  | Tok (Parser.VECTOR [| 1.; 0. |]) -> Some "u"
  | Tok (Parser.VECTOR [| 0.; 1. |]) -> Some "v"
  | Ident s -> Some s
  | _ -> None

(* ---------- the body parser (recursive descent over raw tokens) ---------- *)

type st = {
  toks : token array;
  mutable i : int;
  mutable slots : (string * int) list;  (** innermost first *)
  mutable nslots : int;
  resolve : string -> resolved;
  mutable unsupported : string option;
}

let peek st = st.toks.(st.i).raw
let tok st = st.toks.(st.i)
let advance st = st.i <- st.i + 1
let err st fmt = Diag.error (tok st).loc fmt

let expect st t what =
  match peek st with
  | Tok x when x = t -> advance st
  | r -> err st "in a function: expected %s, found %s" what (describe r)

let call_fn st loc (f : Fn.t) args =
  let n = Fn.arity f in
  if List.length args <> n then
    Diag.error loc "this function takes %d argument%s, got %d" n (if n = 1 then "" else "s")
      (List.length args);
  (match (Fn.unsupported f, st.unsupported) with
  | Some u, None -> st.unsupported <- Some u
  | _ -> ());
  let args = Array.of_list args in
  let code = Fn.code f and size = Fn.nslots f in
  if Array.for_all (function K _ -> true | C _ -> false) args && Fn.unsupported f = None then
    let slots = Array.make size 0. in
    Array.iteri (fun i a -> match a with K k -> slots.(i) <- k | C _ -> ()) args;
    K (code slots)
  else
    let args = Array.map run args in
    C
      (fun s ->
        let slots = Array.make size 0. in
        Array.iteri (fun i a -> slots.(i) <- a s) args;
        code slots)

(* Precedence as in POV-Ray's function parser (fnsyntax.cpp), lowest
   first: |, &, comparisons (one level), + -, * /, unary + -. There is no
   !, ?: or ^ in functions. *)
let rec expr st =
  let rec go a =
    match peek st with
    | Tok Parser.OR -> advance st; go (lift2 (fun x y -> b2f (x <> 0. || y <> 0.)) a (conj st))
    | _ -> a
  in
  go (conj st)

and conj st =
  let rec go a =
    match peek st with
    | Tok Parser.AND -> advance st; go (lift2 (fun x y -> b2f (x <> 0. && y <> 0.)) a (rel st))
    | _ -> a
  in
  go (rel st)

and rel st =
  let rec go a =
    let op g = advance st; go (lift2 (fun x y -> b2f (g x y)) a (add st)) in
    match peek st with
    | Tok Parser.LT -> op ( < )
    | Tok Parser.LE -> op ( <= )
    | Tok Parser.GT -> op ( > )
    | Tok Parser.GE -> op ( >= )
    | Tok Parser.EQ -> op (fun x y -> Float.abs (x -. y) <= 1e-10)
    | Tok Parser.NE -> op (fun x y -> Float.abs (x -. y) > 1e-10)
    | _ -> a
  in
  go (add st)

and add st =
  let rec go a =
    match peek st with
    | Tok Parser.PLUS -> advance st; go (lift2 ( +. ) a (mul st))
    | Tok Parser.MINUS -> advance st; go (lift2 ( -. ) a (mul st))
    | _ -> a
  in
  go (mul st)

and mul st =
  let rec go a =
    match peek st with
    | Tok Parser.STAR -> advance st; go (lift2 ( *. ) a (unary st))
    | Tok Parser.SLASH -> advance st; go (lift2 ( /. ) a (unary st))
    | _ -> a
  in
  go (unary st)

and unary st =
  match peek st with
  | Tok Parser.MINUS -> advance st; lift1 Float.neg (unary st)
  | Tok Parser.PLUS -> advance st; unary st
  | _ -> primary st

and args st =
  expect st Parser.LPAREN "'('";
  match peek st with
  | Tok Parser.RPAREN -> advance st; []
  | _ ->
      let rec go acc =
        let e = expr st in
        match peek st with
        | Tok Parser.COMMA -> advance st; go (e :: acc)
        | Tok Parser.RPAREN -> advance st; List.rev (e :: acc)
        | r -> err st "in a function: expected ',' or ')', found %s" (describe r)
      in
      go []

and primary st =
  let t = tok st in
  match t.raw with
  | Tok (Parser.FLOAT f) -> advance st; K f
  | Tok Parser.LPAREN ->
      advance st;
      let e = expr st in
      expect st Parser.RPAREN "')'";
      e
  | Tok (Parser.VECTOR _) ->
      (* x, y, z (and u, v, t) are the default parameters' names *)
      let name = Option.get (word t.raw) in
      advance st;
      slot st t.loc name
  | Tok (Parser.FUNC name) ->
      advance st;
      builtin st t.loc name
  | Ident "internal" ->
      advance st;
      (match args st with
      | [ K n ] ->
          st.unsupported <-
            Some (Printf.sprintf "POV-Ray's internal function %d is not supported by camlray"
                    (int_of_float n));
          K 0.
      | _ -> Diag.error t.loc "internal() takes one number")
  | Ident (("sum" | "prod") as kind) ->
      advance st;
      fold st t.loc kind
  | Ident "pattern" | Tok Parser.PIGMENT ->
      let kind = match t.raw with Tok Parser.PIGMENT -> "pigment" | _ -> "pattern" in
      advance st;
      skip_braces st;
      st.unsupported <- Some (Printf.sprintf "%s functions are not supported by camlray" kind);
      K 0.
  | Ident name -> (
      advance st;
      match List.assoc_opt name st.slots with
      | Some i -> C (fun s -> s.(i))
      | None -> (
          match st.resolve name with
          | Const k -> K k
          | Vec _ ->
              Diag.error t.loc "%s is a vector: functions take only floats (POV-Ray's rule)" name
          | Func f -> call_fn st t.loc f (args st)
          | Unknown -> Diag.error t.loc "undefined identifier %s in a function" name))
  | r -> err st "in a function: unexpected %s" (describe r)

and slot st loc name =
  match List.assoc_opt name st.slots with
  | Some i -> C (fun s -> s.(i))
  | None -> (
      match name with
      | "u" when List.mem_assoc "x" st.slots -> slot st loc "x"
      | "v" when List.mem_assoc "y" st.slots -> slot st loc "y"
      | _ -> Diag.error loc "%s is not a parameter of this function" name)

and skip_braces st =
  expect st Parser.LBRACE "'{'";
  let rec go depth =
    match peek st with
    | Eof -> err st "unclosed '{' in a function"
    | Tok Parser.LBRACE -> advance st; go (depth + 1)
    | Tok Parser.RBRACE -> advance st; if depth > 0 then go (depth - 1)
    | _ -> advance st; go depth
  in
  go 0

and fold st loc kind =
  (* sum(i, from, to, expr) / prod(i, from, to, expr) *)
  expect st Parser.LPAREN "'('";
  let var = match peek st with
    | Ident v -> advance st; v
    | r -> err st "expected the %s variable, found %s" kind (describe r)
  in
  expect st Parser.COMMA "','";
  let lo = run (expr st) in
  expect st Parser.COMMA "','";
  let hi = run (expr st) in
  expect st Parser.COMMA "','";
  let i = st.nslots in
  st.nslots <- st.nslots + 1;
  let saved = st.slots in
  st.slots <- (var, i) :: saved;
  let body = run (expr st) in
  st.slots <- saved;
  expect st Parser.RPAREN "')'";
  ignore loc;
  let sum = kind = "sum" in
  C
    (fun s ->
      let a = lo s and b = hi s in
      let acc = ref (if sum then 0. else 1.) in
      let k = ref a in
      while !k <= b do
        s.(i) <- !k;
        let v = body s in
        acc := if sum then !acc +. v else !acc *. v;
        k := !k +. 1.
      done;
      !acc)

and builtin st loc name =
  let a = args st in
  let n = List.length a in
  let need k =
    if n <> k then Diag.error loc "%s expects %d argument%s, got %d" name k (if k = 1 then "" else "s") n
  in
  match List.assoc_opt name unary_builtins with
  | Some g -> need 1; lift1 g (List.hd a)
  | None -> (
      match List.assoc_opt name binary_builtins with
      | Some g -> need 2; lift2 g (List.nth a 0) (List.nth a 1)
      | None -> (
          match (name, a) with
          | ("min" | "max"), x :: rest ->
              let g = if name = "min" then Float.min else Float.max in
              List.fold_left (lift2 g) x rest
          | "select", [ c; x; y ] ->
              let c = run c and x = run x and y = run y in
              C (fun s -> if c s < 0. then x s else y s)
          | "select", [ c; x; y; z ] ->
              let c = run c and x = run x and y = run y and z = run z in
              C (fun s -> let v = c s in if v < 0. then x s else if v = 0. then y s else z s)
          | "select", _ -> Diag.error loc "select expects 3 or 4 arguments, got %d" n
          | ("min" | "max"), [] -> Diag.error loc "%s needs at least one argument" name
          | _ -> Diag.error loc "%s cannot be used in a function" name))

let compile ~resolve ~params toks =
  let st = { toks; i = 0; slots = List.mapi (fun i p -> (p, i)) params;
             nslots = List.length params; resolve; unsupported = None } in
  let body = expr st in
  (match peek st with
  | Eof -> ()
  | Tok (Parser.MEMBER m) ->
      (* a pigment function's colour channel: F(x,y,z).gray *)
      err st "in a function: .%s of a function's value is not supported by camlray" m
  | r -> err st "in a function: expected an operator or '}', found %s" (describe r));
  Fn.make ~params:(Array.of_list params) ~nslots:st.nslots ~unsupported:st.unsupported (run body)

