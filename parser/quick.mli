(** Plain expressions of directives evaluated without the parser.

    Directives read their expressions through sub-parses of the grammar
    ([#declare X = ...;], [#if (...)], [#while (...)], [#for], [#write]
    items, macro arguments, array indices, [trace]'s arguments), and the
    table-driven parser spends some five reductions on each token. Where
    the phrase is a plain expression, its tokens already lexed in the top
    frame, it is read here by recursive descent following the grammar's
    [expr] rules, then evaluated with the same functions ({!Value.binop},
    {!Value.call}, {!Gram.vector_literal}, ...), the same spans and in the
    same order as the parser's actions.

    Plain: literals, operators, parentheses, members, calls of built-in
    and declared functions, vector literals of 2 to 5 components written
    with commas, and names whose reading has no effect of its own (a
    built-in, [version], a declared float, vector, string or function that
    is not deprecated), the whole followed by the token that ends the
    sub-parse. Anything else (a macro, an array element, a spline, an
    object, [trace], a directive, the end of the frame, a token not lexed
    yet, a syntax error, a phrase that would pass the token limit) is
    read by the parser as before, nothing having been read here. The
    reading itself has no effect, so doing the arithmetic once the phrase
    is whole gives the same values, warnings and first error as the
    parser's actions. When an action fails, the phrase has been passed
    over already (the parser would stop at the reduction that fails). *)

val paren_expr : Cursor.t -> Value.t
val expr_then_comma : Cursor.t -> Value.t
val expr_then_rparen : Cursor.t -> Value.t
val expr_then_rbracket : Cursor.t -> Value.t
val expr_then_sep : Cursor.t -> Value.t * bool
val macro_arg : Cursor.t -> Decl.t * bool
(** As [Cursor.parse t Parser.Incremental.E] for the entry point [E] of
    the same name. *)

val declare_value : Cursor.t -> Decl.t option
(** [expr ;] as [declare_rhs] reads it (the ';' passed over), or [None]
    with nothing read. *)
