(** Arithmetic runs folded before the parser sees them.

    In a loop such as [#for (I, 0, N - 1) , <I / (N - 1) * 4 - 2, ...>
    #end] most tokens are numbers and operators, and the table-driven
    parser spends some five reductions on each number. Where the grammar
    reads a whole expression (after [, < ( \[ {] and at the start of a
    sub-parse), a run of float operands ([FLOAT], float identifiers,
    parenthesised runs, calls of pure float functions such as [sin]) joined
    by [+ - * /] and unary signs is read here instead, evaluated with the
    same functions and spans the parser's actions use ({!Value.binop},
    {!Value.neg}, {!Value.call}), in the same order, and handed over as one
    [FLOAT] token spanning the run. A vector literal of 2 to 5 such runs,
    [<a, b, c>], wherever a ['<'] cannot be a comparison, becomes one
    [VECTOR] token: it is a whole primary, whatever stands around it.

    The grammar extends an expression only over [+ - * /] and a member
    ['.x'], and is greedy where POV-Ray is, so a run that ends before any
    other token is the expression the parser would have built. Where the
    run cannot be known to end (a member, a directive, the end of a macro
    body or included file) or holds anything else (a name that is not a
    declared float: a macro, an array element, a deprecated name), every
    token read is given back, in order, and the parser reads them as
    before. What a run reads has no effect of its own (no macro call, no
    warning, no error), so doing its arithmetic once it is whole gives the
    same warnings and the same first error, in the same order, as the
    parser's actions. Tokens are read in the parser's order and never
    further ahead than its one-token lookahead. *)

val may_start : Cursor.t -> (Parser.token * Loc.t) option -> Parser.token -> bool
(** [may_start t last tok]: whether a run may start with [tok], just read,
    after [last], the last token the parser was given ([None] at the start
    of a sub-parse); a number is a run only if an operator follows. *)

val run :
  Cursor.t ->
  next:(Cursor.t -> Parser.token * Loc.t) ->
  accepts:(Parser.token -> bool) ->
  Parser.token * Loc.t ->
  (Parser.token * Loc.t) * (Parser.token * Loc.t) list
(** [run t ~next first]: [first] was just read by [next]. Either the run
    starting there, folded, with the tokens it was read from (for the
    parser to be given instead if it refuses the run: its error message
    is then the one it would have given), or [(first, [])], anything read
    after [first] being given back. A vector that a [,] or [}] follows is
    given as [VECTOR_END] where the parser [accepts] it (a whole
    parameter). *)

val replay :
  Cursor.t -> accepts:(Parser.token -> bool) -> Parser.token * Loc.t -> (Parser.token * Loc.t) option
(** [replay t ~accepts first]: [first], a ['<'] just read from the top
    frame, starts a vector run already read at this position of a loop or
    a macro body: the run read again from what was kept of it, its tokens
    passed over, if the parser [accepts] a vector here and the run's
    names are still floats read without a side effect. [None] otherwise,
    nothing read. *)
