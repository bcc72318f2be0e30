(** Reads the body of a [function { ... }] into an {!Fn.t}. Parameters
    default to [x], [y], [z] ([u], [v] are synonyms of [x], [y]).
    Declared floats are read when the function is
    defined (POV-Ray's rule); declared functions may be called. Bodies
    may use [+ - * /], comparisons, [&], [|] (with POV-Ray's function
    precedence: [&] binds tighter than [|]; no [!], [?:] or [^]), the float
    built-ins, [sum(i, a, b, e)] and [prod(i, a, b, e)], and members of
    vector and pigment functions' values ([F(x, y, z).gray], see
    {!Fn.member}). [internal(n)] and [pattern {...}] bodies are accepted
    but marked {!Fn.unsupported}, and so are calls of such functions
    (whatever their number of arguments). Evaluation allocates nothing. *)

type resolved = Const of float | Vec of float array | Func of Fn.t | Unknown
(** What a name other than a parameter means, at definition time
    (the resolver is given where the name stands). *)

val word : Lexer.raw -> string option
(** The name a token stands for as a parameter ([x] is a keyword token). *)

val compile : resolve:(Loc.t -> string -> resolved) -> params:string list -> Lexer.token array -> Fn.t
(** Compile a body given as its tokens (without the braces), ending with
    [Eof]. Raises {!Diag.Error} at the offending token. *)
