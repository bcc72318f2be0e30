(* The expression language, directive entry points and transformations.
   Directives never reach this grammar: the token supplier (Supplier)
   evaluates them and hands over identifiers already typed by what they
   are bound to (FLOAT_ID, OBJECT_ID, ...). Semantic actions evaluate as
   they go, as POV-Ray does; errors in them raise Diag.Error. The grammar
   is split over the grammar_*.mly files, merged by menhir into Parser;
   nonterminals marked %public are extended in several files. *)
%{
open Camlray
open Gram
%}

%token <float> FLOAT
%token <string> STRING
%token <float array> VECTOR
(* a vector literal (Fold) that a ',' or '}' follows: a whole
   parameter, given as one *)
%token <float array> VECTOR_END
%token <float> FLOAT_ID
%token <float array> VECTOR_ID
%token <string> STRING_ID
%token <Sdl.obj> OBJECT_ID
%token <Camlray.Pigment.t> PIGMENT_ID
%token <Camlray.Finish.t> FINISH_ID
%token <Camlray.Texture.t> TEXTURE_ID
%token <Camlray.Interior.t> INTERIOR_ID
%token <Camlray.Transform.t> TRANSFORM_ID
%token <Sdl.camera_item list> CAMERA_ID
%token <string> UNDEFINED_ID
%token <Fn.t> FUNCTION_ID
%token <Fn.t> FUNCTION_LIT  (* a function { ... } the supplier compiled *)
%token <int * int * Fn.t * string option> FUNCTION_SIZED  (* height_field's function W, H { ... } *)
%token <string> FUNC
%token <string> MEMBER
%token <string> RGB
%token <string> CHANNEL
%token LBRACE RBRACE LPAREN RPAREN LBRACKET RBRACKET
%token LT GT LE GE EQ NE PLUS MINUS STAR SLASH COMMA SEMI QUESTION COLON AND OR BANG
%token EOF
%token COLOR SCALE ROTATE TRANSLATE MATRIX TRANSFORM INVERSE

(* Greedy parsing where POV-Ray is greedy: a parameter extends over a
   following '+'/'-', a member access binds to the nearest value. *)
%nonassoc below_shift
%nonassoc PLUS MINUS RGB

%start <Decl.t> declare_rhs
%start <Value.t> paren_expr
%start <Value.t> expr_then_semi
%start <Value.t> expr_then_comma
%start <Value.t> expr_then_lbrace
%start <Value.t> expr_then_rparen
%start <Value.t * bool> expr_then_sep
%start <Value.t> expr_then_rbracket
%start <Decl.t * bool> macro_arg
%start <Decl.t * bool> array_elem
%start <string> string_arg
%start <Transform.t> transform_arg
%start <unit> default_body

%%

%public declare_rhs:
  | v = color_value SEMI { Decl.Value v }
  | o = OBJECT_ID { Decl.Object o }
  | p = PIGMENT_ID { Decl.Pigment p }
  | f = FINISH_ID { Decl.Finish f }
  | t = TEXTURE_ID { Decl.Texture t }
  | i = INTERIOR_ID { Decl.Interior i }
  | t = TRANSFORM_ID { Decl.Transform t }
  | c = CAMERA_ID { Decl.Camera c }
  | f = FUNCTION_LIT { Decl.Function f }
  | o = object_ { Decl.Object o }
  | PIGMENT LBRACE p = pigment_body RBRACE { Decl.Pigment p }
  | FINISH LBRACE f = finish_body RBRACE { Decl.Finish f }
  | TEXTURE LBRACE t = texture_body RBRACE { Decl.Texture t }
  | INTERIOR LBRACE i = interior_body RBRACE { Decl.Interior i }
  | TRANSFORM LBRACE t = transform_body RBRACE { Decl.Transform t }
  | CAMERA LBRACE c = camera_body RBRACE { Decl.Camera c }

%public paren_expr: LPAREN e = expr RPAREN { e }

%public expr_then_semi: e = expr SEMI { e }
%public expr_then_lbrace: e = expr LBRACE { e }

%public expr_then_comma: e = expr COMMA { e }

%public expr_then_rparen: e = expr RPAREN { e }

(* an argument, then [true] when another follows *)
%public expr_then_sep:
  | e = expr COMMA { (e, true) }
  | e = expr RPAREN { (e, false) }

%public expr_then_rbracket: e = expr RBRACKET { e }

%public macro_arg:
  | d = any_value COMMA { (d, false) }
  | d = any_value RPAREN { (d, true) }

(* array elements: no comparisons at the top level, so that <1,2> <3,4>
   (commas between elements are optional) is two vectors *)
%public array_elem:
  | d = value_of(elem_color) COMMA { (d, false) }
  | d = value_of(elem_color) RBRACE { (d, true) }

%public elem_color:
  | e = param ms = list(channel) { List.fold_left (fun v (l, c, x) -> Value.set_channel l v c x) e ms }
  | COLOR e = param ms = list(channel) { List.fold_left (fun v (l, c, x) -> Value.set_channel l v c x) e ms }

%public string_arg:
  | s = STRING { s }
  | s = STRING_ID { s }
  | f = FUNC LPAREN args = separated_list(COMMA, expr) RPAREN
      { Value.to_string_value (loc $loc) (Value.call (loc $loc) f args) }

(* function { transform { ... } }: the supplier hands over the tokens
   from 'transform' on *)
%public transform_arg:
  | TRANSFORM LBRACE t = transform_body RBRACE { t }
  | TRANSFORM t = TRANSFORM_ID { t }

%public default_body:
  | LBRACE ds = list(default_item) RBRACE { List.iter (fun f -> f ()) ds }

%public default_item:
  | FINISH LBRACE f = finish_body RBRACE { fun () -> Defaults.set_finish f }
  | PIGMENT LBRACE p = pigment_body RBRACE { fun () -> Defaults.set_pigment p }
  | TEXTURE LBRACE t = texture_body RBRACE
      { let t = List.hd t in
        fun () -> Defaults.set_pigment t.Texture.pigment; Defaults.set_finish t.Texture.finish }

%public any_value: d = value_of(color_value) { d }

%public value_of(V):
  | o = OBJECT_ID { Decl.Object o }
  | p = PIGMENT_ID { Decl.Pigment p }
  | f = FINISH_ID { Decl.Finish f }
  | t = TEXTURE_ID { Decl.Texture t }
  | i = INTERIOR_ID { Decl.Interior i }
  | t = TRANSFORM_ID { Decl.Transform t }
  | c = CAMERA_ID { Decl.Camera c }
  | f = FUNCTION_ID { Decl.Function f }
  | f = FUNCTION_LIT { Decl.Function f }
  | v = V { Decl.Value v }
  | o = object_ { Decl.Object o }
  | PIGMENT LBRACE p = pigment_body RBRACE { Decl.Pigment p }
  | FINISH LBRACE f = finish_body RBRACE { Decl.Finish f }
  | TEXTURE LBRACE t = texture_body RBRACE { Decl.Texture t }
  | INTERIOR LBRACE i = interior_body RBRACE { Decl.Interior i }
  | TRANSFORM LBRACE t = transform_body RBRACE { Decl.Transform t }

%public expr:
  | c = logic QUESTION a = expr COLON b = expr
      { if Value.to_bool (loc $loc(c)) c then a else b }
  | e = logic { e }

%public logic:
  | a = logic AND b = rel { Value.binop (loc $loc) "&" a b }
  | a = logic OR b = rel { Value.binop (loc $loc) "|" a b }
  | e = rel { e }

%public rel:
  | a = rel LT b = add { Value.binop (loc $loc) "<" a b }
  | a = rel LE b = add { Value.binop (loc $loc) "<=" a b }
  | a = rel GT b = add { Value.binop (loc $loc) ">" a b }
  | a = rel GE b = add { Value.binop (loc $loc) ">=" a b }
  | a = rel EQ b = add { Value.binop (loc $loc) "=" a b }
  | a = rel NE b = add { Value.binop (loc $loc) "!=" a b }
  | e = add { e }

(* Object and keyword parameters: no comparisons at the top level, so that
   the next '<' starts a vector (POV-Ray's commas are often optional). *)

%public add:
  | a = add PLUS b = mul { Value.binop (loc $loc) "+" a b }
  | a = add MINUS b = mul { Value.binop (loc $loc) "-" a b }
  | e = mul { e }
  (* POV-Ray reads a whole expression after rgb: rgb 0.2 + 0.5 is
     rgb 0.7, not rgb 0.2 plus 0.5 in every channel (filter and transmit
     too) *)
  | k = RGB e = add %prec below_shift { Value.rgb_kind (loc $loc) k e }

%public mul:
  | a = mul STAR b = unary { Value.binop (loc $loc) "*" a b }
  | a = mul SLASH b = unary { Value.binop (loc $loc) "/" a b }
  | e = unary { e }

%public unary:
  | MINUS e = unary { Value.neg (loc $loc) e }
  | PLUS e = unary { e }
  | BANG e = unary { Value.not_ (loc $loc) e }
  | e = postfix { e }

%public postfix:
  | e = primary { e }
  | e = postfix m = MEMBER { Value.dot_member (loc $loc) e m }

%public primary:
  | f = FLOAT { Value.Float f }
  | f = FLOAT_ID { Value.Float f }
  | v = VECTOR { Value.Vector v }
  | v = VECTOR_ID { Value.Vector v }
  | s = STRING { Value.String s }
  | s = STRING_ID { Value.String s }
  | LPAREN e = expr RPAREN { e }
  | LT cs = vector_items ioption(COMMA) GT { vector_literal (loc $loc) (List.rev cs) }
  | f = FUNC LPAREN args = separated_list(COMMA, expr) RPAREN { Value.call (loc $loc) f args }
  | f = FUNCTION_ID LPAREN args = separated_list(COMMA, expr) RPAREN { call_function (loc $loc) f args }

%public param:
  | e = add %prec below_shift { e }
  | v = VECTOR_END { Value.Vector v }

(* POV-Ray lets vector components go without commas: <0 20 0> *)
%public vector_more:
  | COMMA e = add { e }
  | e = add_nosign { e }

(* the components, last first (left-recursive, so that a trailing comma,
   which POV-Ray accepts, needs no lookahead) *)
vector_items:
  | c = add { [ c ] }
  | cs = vector_items c = vector_more { c :: cs }

(* a component written without a comma cannot start with a sign: <1 -2>
   is one component, 1 - 2 *)
%public add_nosign:
  | a = add_nosign PLUS b = mul { Value.binop (loc $loc) "+" a b }
  | a = add_nosign MINUS b = mul { Value.binop (loc $loc) "-" a b }
  | e = mul_nosign { e }

%public mul_nosign:
  | a = mul_nosign STAR b = unary { Value.binop (loc $loc) "*" a b }
  | a = mul_nosign SLASH b = unary { Value.binop (loc $loc) "/" a b }
  | e = postfix { e }

(* a colour: optional 'color', a value, then channel settings *)

%public color_value:
  | e = expr ms = list(channel) { List.fold_left (fun v (l, c, x) -> Value.set_channel l v c x) e ms }
  | COLOR e = expr ms = list(channel) { List.fold_left (fun v (l, c, x) -> Value.set_channel l v c x) e ms }
  | COLOR? ms = nonempty_list(channel)
      { List.fold_left (fun v (l, c, x) -> Value.set_channel l v c x) (Value.Vector (Array.make 5 0.)) ms }

%public channel: c = CHANNEL e = param { (loc $loc, c, fl $loc(e) e) }

%public transformation:
  | SCALE e = param { Transform.scale (nonzero_scale $loc(e) (v3 $loc(e) e)) }
  | ROTATE e = param { Transform.rotate (v3 $loc(e) e) }
  | TRANSLATE e = param { Transform.translate (v3 $loc(e) e) }
  | MATRIX e = param
      { match e with
        | Value.Vector a when Array.length a = 12 -> (
            match Transform.of_pov_matrix a with
            | Some t -> t
            | None -> Diag.error (loc $loc) "this matrix is singular")
        | _ -> Diag.error (loc $loc) "matrix needs 12 numbers <a,b,c, d,e,f, g,h,i, j,k,l>" }
  | TRANSFORM t = TRANSFORM_ID { t }
  | TRANSFORM LBRACE t = transform_body RBRACE { t }

%public transform_body:
  (* POV-Ray keeps a transform { } as a transformation, even of a shape
     whose own numbers a translate or scale would change *)
  | ts = list(transform_item) { Transform.opaque (List.fold_left (fun acc f -> f acc) Transform.identity ts) }

%public transform_item:
  | t = transformation { fun acc -> Transform.then_ acc t }
  | t = TRANSFORM_ID { fun acc -> Transform.then_ acc t }
  | INVERSE { fun acc -> Transform.inverse acc }
