(* The body parser of user-defined functions: recursive descent over the
   raw tokens of a function { ... } body, producing Fn closures.
   Constants fold at compile time. *)
open Lexer

type resolved = Const of float | Vec of float array | Func of Fn.t | Unknown

(* A compiled sub-expression: a constant (folded at compile time), or a
   slot of the frame holding the value once [code] (if any) has run. The
   code of a node runs its operands' code, then stores its own value:
   closures returning unit over a float array, so that evaluation
   allocates nothing (a closure returning a float would box it). *)
type c = K of float | V of { slot : int; code : Fn.code option }

let nothing : Fn.code = fun _ _ -> ()

type op1 =
  | Neg | Sin | Cos | Tan | Asin | Acos | Atan | Sinh | Cosh | Tanh | Asinh | Acosh | Atanh | Sqrt
  | Exp | Ln | Log | Abs | Floor | Ceil | Int | Radians | Degrees

type op2 =
  | Add | Sub | Mul | Div | Lt | Le | Gt | Ge | Eq | Ne | And | Or | Atan2 | Pow | Mod | Idiv | Min | Max

let deg = 180. /. Float.pi
let[@inline] b2f b = if b then 1. else 0.

(* inlined into the nodes' code: the match runs, the floats stay unboxed *)
let[@inline] apply1 op x =
  match op with
  | Neg -> -.x
  | Sin -> Float.sin x
  | Cos -> Float.cos x
  | Tan -> Float.tan x
  | Asin -> Float.asin x
  | Acos -> Float.acos x
  | Atan -> Float.atan x
  | Sinh -> Float.sinh x
  | Cosh -> Float.cosh x
  | Tanh -> Float.tanh x
  | Asinh -> Float.log (x +. Float.sqrt ((x *. x) +. 1.))
  | Acosh -> Float.log (x +. Float.sqrt ((x *. x) -. 1.))
  | Atanh -> 0.5 *. Float.log ((1. +. x) /. (1. -. x))
  | Sqrt -> Float.sqrt x
  | Exp -> Float.exp x
  | Ln -> Float.log x
  | Log -> Float.log10 x
  | Abs -> Float.abs x
  | Floor -> Float.floor x
  | Ceil -> Float.ceil x
  | Int -> Float.trunc x
  | Radians -> x /. deg
  | Degrees -> x *. deg

let[@inline] apply2 op x y =
  match op with
  | Add -> x +. y
  | Sub -> x -. y
  | Mul -> x *. y
  | Div -> x /. y
  | Lt -> b2f (x < y)
  | Le -> b2f (x <= y)
  | Gt -> b2f (x > y)
  | Ge -> b2f (x >= y)
  | Eq -> b2f (Float.abs (x -. y) <= 1e-10)
  | Ne -> b2f (Float.abs (x -. y) > 1e-10)
  | And -> b2f (x <> 0. && y <> 0.)
  | Or -> b2f (x <> 0. || y <> 0.)
  | Atan2 -> Float.atan2 x y
  | Pow -> Float.pow x y
  | Mod -> Float.rem x y
  | Idiv -> Float.trunc (x /. y)
  | Min -> if y < x then y else x
  | Max -> if y > x then y else x

let unary_builtins =
  [ ("sin", Sin); ("cos", Cos); ("tan", Tan); ("asin", Asin); ("acos", Acos); ("atan", Atan);
    ("sinh", Sinh); ("cosh", Cosh); ("tanh", Tanh); ("asinh", Asinh); ("acosh", Acosh);
    ("atanh", Atanh); ("sqrt", Sqrt); ("exp", Exp); ("ln", Ln); ("log", Log); ("abs", Abs);
    ("floor", Floor); ("ceil", Ceil); ("int", Int); ("radians", Radians); ("degrees", Degrees) ]

let binary_builtins = [ ("atan2", Atan2); ("pow", Pow); ("mod", Mod); ("div", Idiv) ]

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
  mutable slots : (string * int) list;  (** parameters and sum/prod variables, innermost first *)
  mutable nslots : int;  (** this function's own slots *)
  resolve : Loc.t -> string -> resolved;
  mutable unsupported : string option;
  mutable consts : (int * float) list;  (** slots holding constants, written on entry *)
  mutable callee : int;  (** the largest frame of a function called *)
  mutable subst : (int * float) list;  (** tokens naming declared floats, and their values *)
  top : int ref;
      (** where called functions' frames start, after the own slots (known
          once the body is compiled) *)
}

let peek st = st.toks.(st.i).raw
let tok st = st.toks.(st.i)
let advance st = st.i <- st.i + 1
let err st fmt = Diag.error (tok st).loc fmt

let expect st t what =
  match peek st with
  | Tok x when x = t -> advance st
  | r -> err st "in a function: expected %s, found %s" what (describe r)

let fresh st =
  let i = st.nslots in
  st.nslots <- i + 1;
  i

(* an operand: the slot to read and the code that fills it *)
let operand st = function
  | K k ->
      let i = fresh st in
      st.consts <- (i, k) :: st.consts;
      (i, nothing)
  | V { slot; code } -> (slot, Option.value code ~default:nothing)

let[@inline] get (s : float array) i = Array.unsafe_get s i
let[@inline] set (s : float array) i v = Array.unsafe_set s i v

let un st op a =
  match a with
  | K x -> K (apply1 op x)
  | _ ->
      let ia, ra = operand st a in
      let o = fresh st in
      V { slot = o; code = Some (fun s b -> ra s b; set s (b + o) (apply1 op (get s (b + ia)))) }

(* pow(a, n) for a constant n of 0, 2, 3, ..., 8, as POV-Ray's function
   compiler writes it (fncode.cpp): 1 for 0, else a chain of products,
   which rounds otherwise than the C library's pow (x^3 is (x x) x, x^6
   is ((x x)(x x))(x x), ...) *)
let[@inline] ipow n x =
  match n with
  | 2 -> x *. x
  | 3 -> x *. x *. x
  | 4 -> let y = x *. x in y *. y
  | 5 -> let y = x *. x in (y *. y) *. x
  | 6 -> let y = x *. x in (y *. y) *. y
  | 7 -> let y = x *. x in ((y *. y) *. x) *. y
  | _ -> let y = x *. x in let y = y *. y in y *. y

let bin st op a b =
  match (a, b) with
  | K x, K y -> K (apply2 op x y)
  | _, K 0. when op = Pow -> K 1.
  | _, K y when op = Pow && Float.is_integer y && y >= 2. && y <= 8. ->
      let n = int_of_float y in
      let ia, ra = operand st a in
      let o = fresh st in
      V { slot = o; code = Some (fun s k -> ra s k; set s (k + o) (ipow n (get s (k + ia)))) }
  | _ ->
      let ia, ra = operand st a and ib, rb = operand st b in
      let o = fresh st in
      V
        {
          slot = o;
          code =
            Some
              (fun s k ->
                ra s k;
                rb s k;
                set s (k + o) (apply2 op (get s (k + ia)) (get s (k + ib))));
        }

(* operands' slots and code, in arrays (the code loops over them) *)
let operands st args =
  let ops = List.map (operand st) args in
  (Array.of_list (List.map fst ops), Array.of_list (List.map snd ops))

let call_fn st loc name (f : Fn.t) args =
  match Fn.unsupported f with
  | Some u ->
      (* the name it is called by, for POV-Ray's internal functions
         (functions.inc's f_sphere is internal(61)) *)
      let u =
        let tail = " is not supported by camlray" in
        let n = String.length u and k = String.length tail in
        if String.length u > 7 && String.sub u 0 7 = "POV-Ray" && n > k && String.sub u (n - k) k = tail then
          Printf.sprintf "%s (%s)%s" name (String.sub u 0 (n - k)) tail
        else u
      in
      (* POV-Ray's internal functions take their own number of arguments:
         the call is read, and the function calling it is unsupported *)
      if st.unsupported = None then st.unsupported <- Some u;
      K 0.
  | None ->
  let n = Fn.arity f in
  if List.length args <> n then
    Diag.error loc "this function takes %d argument%s, got %d" n (if n = 1 then "" else "s")
      (List.length args);
  if Fn.is_vector f then
    Diag.error loc "this is a vector function: take a component of its value (F(x, y, z).x)";
  if List.for_all (function K _ -> true | V _ -> false) args then
    K (Fn.eval f (Array.of_list (List.map (function K k -> k | V _ -> 0.) args)))
  else begin
    (* the callee's frame starts after this function's own slots *)
    st.callee <- max st.callee (Fn.frame f);
    let slots, codes = operands st args in
    let o = fresh st and top = st.top and run = Fn.run f and fo = Fn.out f in
    V
      {
        slot = o;
        code =
          Some
            (fun s k ->
              for i = 0 to Array.length codes - 1 do
                (Array.unsafe_get codes i) s k
              done;
              let cb = k + !top in
              for i = 0 to Array.length slots - 1 do
                set s (cb + i) (get s (k + Array.unsafe_get slots i))
              done;
              run s cb;
              set s (k + o) (get s (cb + fo)));
      }
  end

(* V(args).member: a vector or pigment function's component *)
let call_member st loc (f : Fn.t) args mloc m =
  let n = Fn.arity f in
  if List.length args <> n then
    Diag.error loc "this function takes %d argument%s, got %d" n (if n = 1 then "" else "s")
      (List.length args);
  let c =
    match Fn.member m with
    | Some c -> c
    | None ->
        Diag.error mloc
          "in a function: .%s is not a member; they are x, y, z, t, u, v, red, green, blue, filter, \
           transmit and gray"
          m
  in
  if not (Fn.is_vector f) then
    Diag.error mloc "in a function: .%s applies to vector and pigment functions; this one returns a float" m;
  let slots, codes = operands st args in
  let o = fresh st in
  let get_member = Fn.member_code mloc f c ~args:slots ~out:o in
  V
    {
      slot = o;
      code =
        Some
          (fun s k ->
            for i = 0 to Array.length codes - 1 do
              (Array.unsafe_get codes i) s k
            done;
            get_member s k);
    }

(* Precedence as in POV-Ray's function parser (fnsyntax.cpp), lowest
   first: |, &, comparisons (one level), + -, * /, unary + -. There is no
   !, ?: or ^ in functions. *)
let rec expr st =
  let rec go a =
    match peek st with
    | Tok Parser.OR -> advance st; go (bin st Or a (conj st))
    | _ -> a
  in
  go (conj st)

and conj st =
  let rec go a =
    match peek st with
    | Tok Parser.AND -> advance st; go (bin st And a (rel st))
    | _ -> a
  in
  go (rel st)

and rel st =
  let rec go a =
    let op o = advance st; go (bin st o a (add st)) in
    match peek st with
    | Tok Parser.LT -> op Lt
    | Tok Parser.LE -> op Le
    | Tok Parser.GT -> op Gt
    | Tok Parser.GE -> op Ge
    | Tok Parser.EQ -> op Eq
    | Tok Parser.NE -> op Ne
    | _ -> a
  in
  go (add st)

and add st =
  let rec go a =
    match peek st with
    | Tok Parser.PLUS -> advance st; go (bin st Add a (mul st))
    | Tok Parser.MINUS -> advance st; go (bin st Sub a (mul st))
    | _ -> a
  in
  go (mul st)

and mul st =
  let rec go a =
    match peek st with
    | Tok Parser.STAR -> advance st; go (bin st Mul a (unary st))
    | Tok Parser.SLASH -> advance st; go (bin st Div a (unary st))
    | _ -> a
  in
  go (unary st)

and unary st =
  match peek st with
  | Tok Parser.MINUS -> advance st; un st Neg (unary st)
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
  | Tok Parser.INTERNAL ->
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
  | Tok Parser.PIGMENT ->
      (* the supplier reads function { pigment { ... } } itself *)
      err st "in a function: a pigment is a function's whole body: function { pigment { ... } }"
  | Ident "pattern" ->
      advance st;
      skip_braces st;
      st.unsupported <- Some "pattern (in a function) is not supported by camlray";
      K 0.
  | Ident name -> (
      advance st;
      match List.assoc_opt name st.slots with
      | Some i -> V { slot = i; code = None }
      | None -> (
          match st.resolve t.loc name with
          | Const k -> st.subst <- (st.i - 1, k) :: st.subst; K k
          | Vec _ ->
              Diag.error t.loc "%s is a vector: functions take only floats (POV-Ray's rule)" name
          | Func f -> (
              let a = args st in
              match peek st with
              | Tok (Parser.MEMBER m) ->
                  let mloc = (tok st).loc in
                  advance st;
                  call_member st t.loc f a mloc m
              | _ -> call_fn st t.loc name f a)
          | Unknown -> Diag.error t.loc "undefined identifier %s in a function" name))
  | r -> err st "in a function: unexpected %s" (describe r)

and slot st loc name =
  match List.assoc_opt name st.slots with
  | Some i -> V { slot = i; code = None }
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
  (* sum(i, from, to, expr) / prod(i, from, to, expr): the variable runs
     from [from] by steps of 1 while at most [to] (read once) *)
  expect st Parser.LPAREN "'('";
  let var = match peek st with
    | Ident v -> advance st; v
    | r -> err st "expected the %s variable, found %s" kind (describe r)
  in
  expect st Parser.COMMA "','";
  let ilo, rlo = operand st (expr st) in
  expect st Parser.COMMA "','";
  let ihi, rhi = operand st (expr st) in
  expect st Parser.COMMA "','";
  let i = fresh st in
  let saved = st.slots in
  st.slots <- (var, i) :: saved;
  let ib, rbody = operand st (expr st) in
  st.slots <- saved;
  expect st Parser.RPAREN "')'";
  ignore loc;
  let o = fresh st in
  let code =
    if kind = "sum" then fun s k ->
      rlo s k;
      rhi s k;
      set s (k + i) (get s (k + ilo));
      set s (k + o) 0.;
      while get s (k + i) <= get s (k + ihi) do
        rbody s k;
        set s (k + o) (get s (k + o) +. get s (k + ib));
        set s (k + i) (get s (k + i) +. 1.)
      done
    else fun s k ->
      rlo s k;
      rhi s k;
      set s (k + i) (get s (k + ilo));
      set s (k + o) 1.;
      while get s (k + i) <= get s (k + ihi) do
        rbody s k;
        set s (k + o) (get s (k + o) *. get s (k + ib));
        set s (k + i) (get s (k + i) +. 1.)
      done
  in
  V { slot = o; code = Some code }

and select st c x y z =
  (* select(c, x, y [, z]): x when c < 0; with 3 arguments y otherwise,
     with 4 y when c = 0 and z when c > 0; only the branch taken runs *)
  match c with
  | K v -> if v < 0. then x else (match z with None -> y | Some z -> if v = 0. then y else z)
  | _ ->
      let ic, rc = operand st c in
      let ix, rx = operand st x and iy, ry = operand st y in
      let o = fresh st in
      let code =
        match z with
        | None ->
            fun s k ->
              rc s k;
              if get s (k + ic) < 0. then (rx s k; set s (k + o) (get s (k + ix)))
              else (ry s k; set s (k + o) (get s (k + iy)))
        | Some z ->
            let iz, rz = operand st z in
            fun s k ->
              rc s k;
              let v = get s (k + ic) in
              if v < 0. then (rx s k; set s (k + o) (get s (k + ix)))
              else if v = 0. then (ry s k; set s (k + o) (get s (k + iy)))
              else (rz s k; set s (k + o) (get s (k + iz)))
      in
      V { slot = o; code = Some code }

and builtin st loc name =
  let a = args st in
  let n = List.length a in
  let need k =
    if n <> k then Diag.error loc "%s expects %d argument%s, got %d" name k (if k = 1 then "" else "s") n
  in
  match List.assoc_opt name unary_builtins with
  | Some g -> need 1; un st g (List.hd a)
  | None -> (
      match List.assoc_opt name binary_builtins with
      | Some g -> need 2; bin st g (List.nth a 0) (List.nth a 1)
      | None -> (
          match (name, a) with
          | ("min" | "max"), x :: rest ->
              let g = if name = "min" then Min else Max in
              List.fold_left (bin st g) x rest
          | "select", [ c; x; y ] -> select st c x y None
          | "select", [ c; x; y; z ] -> select st c x y (Some z)
          | "select", _ -> Diag.error loc "select expects 3 or 4 arguments, got %d" n
          | ("min" | "max"), [] -> Diag.error loc "%s needs at least one argument" name
          | _ -> Diag.error loc "%s cannot be used in a function" name))

(* the text of a body's token, as the lexer reads it back *)
let token_text (r : raw) =
  match r with
  | Tok (Parser.FLOAT f) -> Printf.sprintf "%.17g" f
  | Tok (Parser.FUNC n) -> n
  | Tok (Parser.MEMBER m) -> "." ^ m
  | Tok Parser.LPAREN -> "(" | Tok Parser.RPAREN -> ")" | Tok Parser.LBRACE -> "{" | Tok Parser.RBRACE -> "}"
  | Tok Parser.COMMA -> "," | Tok Parser.PLUS -> "+" | Tok Parser.MINUS -> "-" | Tok Parser.STAR -> "*"
  | Tok Parser.SLASH -> "/" | Tok Parser.LT -> "<" | Tok Parser.LE -> "<=" | Tok Parser.GT -> ">"
  | Tok Parser.GE -> ">=" | Tok Parser.EQ -> "=" | Tok Parser.NE -> "!=" | Tok Parser.AND -> "&"
  | Tok Parser.OR -> "|"
  | r -> ( match word r with Some w -> w | None -> describe r)

let source st =
  let n = Array.length st.toks in
  let b = Buffer.create 64 in
  for i = 0 to n - 1 do
    match st.toks.(i).raw with
    | Eof -> ()
    | r ->
        if Buffer.length b > 0 then Buffer.add_char b ' ';
        Buffer.add_string b
          (match List.assoc_opt i st.subst with
           | Some k -> if k < 0. then Printf.sprintf "( - %.17g )" (-.k) else Printf.sprintf "%.17g" k
           | None -> token_text r)
  done;
  Buffer.contents b

(* POV-Ray's internal functions camlray has (functions.inc's f_sphere,
   f_torus, f_rounded_box, f_superellipsoid, f_r, f_th, f_ph, f_helix1,
   by the values POV-Ray's own give, checked at 30 random points to
   1e-12; and the noise functions f_noise3d, f_noise_generator, f_ridge,
   f_ridged_mf, f_hetero_mf, POV-Ray's formulas over POV-Ray's noise,
   checked against values POV-Ray wrote, test/fn_pov/): the parameters
   after x, y, z, and the code from slot [b] *)
(* the [i]th argument of a frame at [b]; the helpers below are top-level
   and inlined, not local closures: a float a closure returns is boxed,
   and these run at every step of an isosurface's root search *)
let[@inline] g s b i = get s (b + i)

(* f_rounded_box's per-axis distance *)
let[@inline] box_axis v h r = Float.max (Float.abs v -. h +. r) 0.

(* the noise generator an internal function's argument names, as POV-Ray
   reads it: truncated to an integer, its two low bits (4 is 0, the
   original noise as 1 is; -1 is 3) *)
let[@inline] gen_of v = int_of_float v land 3

(* POV-Ray's noise stretched to [-1, 1] (n * 2 - 1), as the fractal
   functions take it *)
let[@inline] snoise gen x y z = (Camlray.Noise.noise gen x y z *. 2.0) -. 1.0

(* f_ridged_mf's octave: (offset - |n|)^2 of the stretched noise *)
let[@inline] ridged gen offset x y z =
  let n = Float.abs (snoise gen x y z) in
  let r = offset -. n in
  r *. r

(* f_ridge's octave: |noise - ridge| scaled by 1 / max(ridge, 1 - ridge) *)
let[@inline] ridge_octave gen ridge rscale x y z = Float.abs (Camlray.Noise.noise gen x y z -. ridge) *. rscale

(* f_hetero_mf's increment before its weights: the stretched noise plus
   the offset *)
let[@inline] hetero gen offset x y z = snoise gen x y z +. offset

(* C's max of doubles as POV-Ray writes it: [b] when [a < b] *)
let[@inline] cmax (a : float) b = if a < b then b else a

(* f_ridged_mf's exponents lacunarity^(-H i), octave i's weight. POV-Ray
   makes them at the function's first call, from that call's H and
   lacunarity (one table per [function { internal(59) }]), and keeps them
   for every later call whatever its parameters (so two calls with other
   H or lacunarity share the first's weights; its octaves still scale the
   point by their own lacunarity): the same here, the table made once per
   compiled function. POV-Ray's table has octaves + 1 entries (the
   frequency multiplied up, then raised to -H); past them it reads what
   lies beyond, where this one goes on with the same rule, up to 4096 *)
let ridged_exponents h lac octaves =
  let n = if Float.is_nan octaves || octaves < 63. then 64 else if octaves > 4095. then 4096 else int_of_float octaves + 1 in
  let ea = Float.Array.make n 0. in
  let freq = ref 1.0 in
  for i = 0 to n - 1 do
    Float.Array.unsafe_set ea i (Float.pow !freq (-.h));
    freq := !freq *. lac
  done;
  ea

let internal_fn n : (int * Fn.code) option =
  match n with
  | 61 ->
      (* f_sphere: radius *)
      Some (1, fun s b ->
        let x = g s b 0 and y = g s b 1 and z = g s b 2 in
        set s (b + 4) (Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) -. g s b 3))
  | 70 ->
      (* f_torus: major, minor radius (about y) *)
      Some (2, fun s b ->
        let x = g s b 0 and y = g s b 1 and z = g s b 2 in
        let q = Float.sqrt ((x *. x) +. (z *. z)) -. g s b 3 in
        set s (b + 5) (Float.sqrt ((q *. q) +. (y *. y)) -. g s b 4))
  | 60 ->
      (* f_rounded_box: corner radius, half sizes x, y, z (POV-Ray's
         value is 1e-6 below the distance) *)
      Some (4, fun s b ->
        let r = g s b 3 in
        let ax = box_axis (g s b 0) (g s b 4) r and ay = box_axis (g s b 1) (g s b 5) r
        and az = box_axis (g s b 2) (g s b 6) r in
        set s (b + 7) (Float.sqrt ((ax *. ax) +. (ay *. ay) +. (az *. az)) -. r -. 1e-6))
  | 68 ->
      (* f_superellipsoid: east-west, north-south exponents; positive
         inside, as POV-Ray's *)
      Some (2, fun s b ->
        let e = g s b 3 and n = g s b 4 in
        let x = Float.abs (g s b 0) and y = Float.abs (g s b 1) and z = Float.abs (g s b 2) in
        let a = Float.pow (Float.pow (Float.pow x (2. /. e) +. Float.pow y (2. /. e)) (e /. n) +. Float.pow z (2. /. n)) (n /. 2.) in
        set s (b + 5) (1. -. a))
  | 57 ->
      (* f_r: the distance from the origin *)
      Some (0, fun s b ->
        let x = g s b 0 and y = g s b 1 and z = g s b 2 in
        set s (b + 3) (Float.sqrt ((x *. x) +. (y *. y) +. (z *. z))))
  | 69 ->
      (* f_th: the angle about y, atan2(x, z) *)
      Some (0, fun s b -> set s (b + 3) (Float.atan2 (g s b 0) (g s b 2)))
  | 47 ->
      (* f_ph: the angle from +y, atan2(sqrt(x^2 + z^2), y) *)
      Some (0, fun s b ->
        let x = g s b 0 and z = g s b 2 in
        set s (b + 3) (Float.atan2 (Float.sqrt ((x *. x) +. (z *. z))) (g s b 1)))
  | 25 ->
      (* f_helix1: number of helices, period, minor radius, major radius,
         shape, cross section (1 circle, 0 square, else the exponent 2/c
         of a superellipse: 2 a diamond), its rotation in degrees.
         Around y, the angle (from +x towards +z, times the number, plus
         y times period times number, taken into [0, 2 pi)) less pi,
         divided by shape and by period times number, is the section's
         second coordinate; the distance from the major radius its
         first; the value is the section's norm, at most the distance
         from the axis plus the major radius, less the minor radius *)
      Some (7, fun s b ->
        let x = g s b 0 and y = g s b 1 and z = g s b 2 in
        let n = g s b 3 and period = g s b 4 and minor = g s b 5 and major = g s b 6
        and shape = g s b 7 and cross = g s b 8 and turn = g s b 9 in
        let r = Float.sqrt ((x *. x) +. (z *. z)) in
        (* POV-Ray's nudge on the axis (atan2 (0, 0) is 0 anyway) *)
        let x = if x = 0. && z = 0. then 0.000001 else x in
        let two_pi = 2. *. Float.pi in
        let th = Float.rem ((Float.atan2 z x *. n) +. (y *. period *. n)) two_pi in
        let th = if th < 0. then th +. two_pi else th in
        let v = (th -. Float.pi) /. shape /. (period *. n) in
        let u = r -. major in
        let d =
          if cross = 1. then Float.sqrt ((u *. u) +. (v *. v))
          else begin
            (* turned (no tuple: its floats would be boxed) *)
            let c = if turn = 0. then 1. else Float.cos (turn *. (Float.pi /. 180.))
            and sn = if turn = 0. then 0. else Float.sin (turn *. (Float.pi /. 180.)) in
            let u = if turn = 0. then u else (u *. c) -. (v *. sn)
            and v = if turn = 0. then v else (u *. sn) +. (v *. c) in
            if cross <> 0. then
              let e = 2. /. cross in
              Float.pow (Float.pow (Float.abs u) e +. Float.pow (Float.abs v) e) (cross *. 0.5)
            else Float.max (Float.abs u) (Float.abs v)
          end
        in
        set s (b + 10) (Float.min (major +. r) d -. minor))
  | 76 ->
      (* f_noise3d: POV-Ray's noise of the scene's generator
         (global_settings' noise_generator, 2 when none; at parse time the
         last one read so far, as POV-Ray's) *)
      Some (0, fun s b ->
        set s (b + 3) (Camlray.Noise.noise !Camlray.Pattern.scene_noise_generator (g s b 0) (g s b 1) (g s b 2)))
  | 78 ->
      (* f_noise_generator: POV-Ray's noise of the generator given *)
      Some (1, fun s b -> set s (b + 4) (Camlray.Noise.noise (gen_of (g s b 3)) (g s b 0) (g s b 1) (g s b 2)))
  | 58 ->
      (* f_ridge: lambda, octaves, omega, offset, ridge, generator.
         Octave i (from 0, at the point times lambda^i, weight omega^i)
         is |noise - ridge| / max(ridge, 1 - ridge) less the offset; the
         fraction of the octaves one more octave so weighted; the sum over
         the weights' sum, divided by max(offset, 1 - offset) *)
      Some (6, fun s b ->
        let x = g s b 0 and y = g s b 1 and z = g s b 2 in
        let lambda = g s b 3 and oct = g s b 4 and omega = g s b 5 and off = g s b 6 and ridge = g s b 7 in
        let gen = gen_of (g s b 8) in
        let octaves = int_of_float oct in
        let rscale = 1.0 /. cmax ridge (1.0 -. ridge) and scale = 1.0 /. cmax off (1.0 -. off) in
        let resid = oct -. float_of_int octaves in
        let value = ref (ridge_octave gen ridge rscale x y z -. off) in
        let tot = ref 1.0 and l = ref lambda and o = ref omega in
        for _ = 2 to octaves do
          let li = !l in
          let v = ridge_octave gen ridge rscale (x *. li) (y *. li) (z *. li) in
          value := !value +. (!o *. (v -. off));
          tot := !tot +. !o;
          l := li *. lambda;
          o := !o *. omega
        done;
        if resid <> 0.0 then begin
          let li = !l in
          let v = ridge_octave gen ridge rscale (x *. li) (y *. li) (z *. li) in
          value := !value +. (!o *. (v -. off) *. resid);
          tot := !tot +. (!o *. resid)
        end;
        set s (b + 9) (!value *. scale /. !tot))
  | 59 ->
      (* f_ridged_mf: Musgrave's ridged multifractal, H, lacunarity,
         octaves, offset, gain, generator: octave 0 the ridge (offset -
         |n|)^2, each further one (the point times the lacunarity again)
         that ridge weighted by the previous one times the gain (clamped
         to [0, 1]) and by the exponent table's entry *)
      let table = Atomic.make None in
      Some (6, fun s b ->
        let h = g s b 3 and lac = g s b 4 and octaves = g s b 5 and offset = g s b 6 and gain = g s b 7 in
        let gen = gen_of (g s b 8) in
        let ea =
          match Atomic.get table with
          | Some ea -> ea
          | None ->
              let ea = ridged_exponents h lac octaves in
              if Atomic.compare_and_set table None (Some ea) then ea
              else Option.get (Atomic.get table)
        in
        let last = Float.Array.length ea - 1 in
        let x = ref (g s b 0) and y = ref (g s b 1) and z = ref (g s b 2) in
        let signal = ref (ridged gen offset !x !y !z) in
        let result = ref !signal and i = ref 1 in
        while float_of_int !i < octaves do
          x := !x *. lac;
          y := !y *. lac;
          z := !z *. lac;
          let w = !signal *. gain in
          let w = if w > 1.0 then 1.0 else if w < 0.0 then 0.0 else w in
          signal := ridged gen offset !x !y !z *. w;
          result := !result +. (!signal *. Float.Array.unsafe_get ea (if !i < last then !i else last));
          incr i
        done;
        set s (b + 9) !result)
  | 29 ->
      (* f_hetero_mf: Musgrave's heterogeneous multifractal, H,
         lacunarity, octaves, offset, T, generator: the first octave's
         stretched noise plus the offset; each further one (the point
         times the lacunarity again) adds its own, weighted by
         lacunarity^(-H i) and by the sum so far raised to the integer
         part of T; the octaves' fraction one more such increment, times
         the fraction and the sum *)
      Some (6, fun s b ->
        let h = g s b 3 and lac = g s b 4 and octaves = g s b 5 and offset = g s b 6 and t = g s b 7 in
        let gen = gen_of (g s b 8) in
        let signal = ref (hetero gen offset (g s b 0) (g s b 1) (g s b 2)) in
        let x = ref (g s b 0 *. lac) and y = ref (g s b 1 *. lac) and z = ref (g s b 2 *. lac) in
        let step = Float.pow lac (-.h) in
        let ea = ref step and i = ref 1 and times = int_of_float t in
        while float_of_int !i < octaves do
          let inc = ref (hetero gen offset !x !y !z *. !ea) in
          for _ = 1 to times do
            inc := !inc *. !signal
          done;
          signal := !signal +. !inc;
          x := !x *. lac;
          y := !y *. lac;
          z := !z *. lac;
          ea := !ea *. step;
          incr i
        done;
        let rem = octaves -. float_of_int (int_of_float octaves) in
        if rem <> 0.0 then begin
          let inc = hetero gen offset !x !y !z *. !ea in
          signal := !signal +. (rem *. inc *. !signal)
        end;
        set s (b + 9) !signal)
  | _ -> None

let compile ~resolve ~params toks =
  match Array.map (fun (t : token) -> t.raw) toks with
  | [| Tok Parser.INTERNAL; Tok Parser.LPAREN; Tok (Parser.FLOAT n); Tok Parser.RPAREN; Eof |]
    when Float.is_integer n && internal_fn (int_of_float n) <> None && params = [ "x"; "y"; "z" ] ->
      let k, code = Option.get (internal_fn (int_of_float n)) in
      let params = Array.append [| "x"; "y"; "z" |] (Array.init k (Printf.sprintf "p%d")) in
      let np = Array.length params in
      Fn.make ~source:(Printf.sprintf "internal(%d)" (int_of_float n)) ~params ~frame:(np + 1) ~out:np
        ~unsupported:None code
  | _ ->
  let st =
    { toks; i = 0; slots = List.mapi (fun i p -> (p, i)) params; nslots = List.length params; resolve;
      unsupported = None; consts = []; callee = 0; subst = []; top = ref 0 }
  in
  let body = expr st in
  (match peek st with
  | Eof -> ()
  | Tok (Parser.MEMBER m) ->
      err st "in a function: .%s applies only to a call of a vector or pigment function" m
  | r -> err st "in a function: expected an operator or '}', found %s" (describe r));
  let out, code = operand st body in
  st.top := st.nslots;
  let frame = st.nslots + st.callee in
  let cslots = Array.of_list (List.map fst st.consts) and cvals = Array.of_list (List.map snd st.consts) in
  let run =
    if Array.length cslots = 0 then code
    else fun s k ->
      for i = 0 to Array.length cslots - 1 do
        set s (k + Array.unsafe_get cslots i) (Array.unsafe_get cvals i)
      done;
      code s k
  in
  Fn.make ~source:(source st) ~params:(Array.of_list params) ~frame ~out ~unsupported:st.unsupported run
