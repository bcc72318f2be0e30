(** User-defined functions, POV-Ray's [function { ... }] and
    [function (a, b) { ... }]: float expressions over their parameters,
    compiled once into closures ({!Fnparse} reads the bodies), and the
    vector functions [function { transform { ... } }], [function { spline
    { ... } }] and [function { pigment { ... } }]. A value of this module
    is what [#declare F = function {...}] binds and what function
    patterns evaluate. *)

type t

type code = float array -> int -> unit
(** Compiled code runs in a frame: [code s base] reads its parameters
    from [s.(base)], [s.(base + 1)], ... and works in slots [base ..
    base + frame - 1] (the frames of the functions it calls included),
    leaving its value in [s.(base + out)]. It allocates nothing. *)

val make :
  ?source:string -> params:string array -> frame:int -> out:int -> unsupported:string option -> code -> t
(** [make ~params ~frame ~out ~unsupported code], [frame] at least the
    number of parameters, [out] below [frame]; [source] is the body as
    {!source} gives it. *)

val of_transform : Camlray.Transform.t -> t
(** [function { transform { ... } }]: a vector function of [x, y, z]
    giving the transformed point. *)

val of_spline : Spline.t -> t
(** [function { spline { ... } }]: a vector function of one parameter
    (a natural spline's coefficients computed here, once). Raises
    [Invalid_argument] on an empty spline. *)

val of_pigment : Camlray.Pigment.t -> t
(** [function { pigment { ... } }]: a vector function of [x, y, z]
    giving the pigment's colour at that point, [<red, green, blue,
    filter, transmit>]. *)

val is_vector : t -> bool

val frame : t -> int
val out : t -> int
val run : t -> code
(** The compiled code of a float function (a vector function's does
    nothing). *)

val member : string -> int option
(** The component a member name selects from a vector function's value,
    as POV-Ray's functions read it: [x], [u], [red] 0; [y], [v], [green]
    1; [z], [blue] 2; [t], [filter] 3; [transmit] 4; [gray] (or [grey])
    {!gray}, [0.297 red + 0.589 green + 0.114 blue]. *)

val gray : int
(** The index {!member} gives [gray]. *)

val member_code : Loc.t -> t -> int -> args:int array -> out:int -> code
(** [member_code loc f m ~args ~out]: code calling the vector function
    [f] with the values in slots [args] (from the base) and leaving
    component [m] (as {!member} numbers them) of its value in slot
    [out]. The call allocates nothing. A located error
    when [f] is not a vector function, takes another number of
    arguments, or has no such component. *)

val call : Loc.t -> t -> float list -> float
(** A call in an expression, [F(1, 2, 3)]: a located error when the
    argument count is wrong, the function is {!unsupported} or a vector
    function. *)

val call_vector : Loc.t -> t -> float list -> float array
(** A call of a vector function in an expression. *)

val arity : t -> int
val params : t -> string list

val source : t -> string option
(** The body of a float function read by {!Fnparse}, as text that reads
    back to the same function: its tokens, with declared floats written
    as their values (declared functions it calls stay names). *)

val unsupported : t -> string option
(** Why this function cannot be evaluated ([internal(n)], pattern
    functions), if it cannot. *)

val eval : t -> float array -> float
(** Evaluate with one value per parameter. Raises [Invalid_argument] when
    the count is wrong, the function is {!unsupported} or a vector
    function. *)

val eval3 : t -> float -> float -> float -> float
(** [eval3 f] checks once that [f] takes 3 parameters and is supported,
    then returns an evaluator (each call has its own slots). Raises
    [Invalid_argument]. *)

val pattern : Loc.t -> t -> Camlray.Pattern.fn
(** The function as a pattern ([pigment { function { ... } }]): a
    located error unless it is a supported float function of 3
    parameters. *)

val pigment_pattern : Loc.t -> Camlray.Pigment.t -> Camlray.Pattern.fn
(** POV-Ray's [pigment_pattern { P }]: the grey of [P]'s colour
    ([0.297 red + 0.589 green + 0.114 blue]) clipped to [[0, 1]]. *)

val of_pattern : Camlray.Pattern.t -> Camlray.Transform.t -> t
(** [function { pattern { ... } }]: the pattern's value at the point taken
    into its space by the transform's inverse (waves, frequency and
    warps applied, as in a pigment); nothing allocated per call. *)
