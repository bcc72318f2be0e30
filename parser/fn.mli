(** User-defined functions, POV-Ray's [function { ... }] and
    [function (a, b) { ... }]: float expressions over their parameters,
    compiled once into closures ({!Fnparse} reads the bodies). A value of
    this module is what [#declare F = function {...}] binds and what
    isosurfaces and function patterns evaluate. *)

type t

val make :
  params:string array -> nslots:int -> unsupported:string option -> (float array -> float) -> t
(** [make ~params ~nslots ~unsupported code]: [code] reads its arguments
    from slots [0 .. arity-1] of an array of [nslots] floats (further
    slots are scratch for [sum]/[prod]). *)

val of_transform : Camlray.Transform.t -> t
(** [function { transform { ... } }]: a vector function of [x, y, z]
    giving the transformed point. *)

val of_spline : (float -> float array) -> t
(** [function { spline { ... } }]: a vector function of one parameter. *)

val is_vector : t -> bool

val call_vector : Loc.t -> t -> float list -> float array
(** A call of a vector function in an expression. *)

val code : t -> float array -> float
val nslots : t -> int

val call : Loc.t -> t -> float list -> float
(** A call in an expression, [F(1, 2, 3)]: a located error when the
    argument count is wrong, the function is {!unsupported} or a vector
    function. *)

val arity : t -> int
val params : t -> string list

val unsupported : t -> string option
(** Why this function cannot be evaluated ([internal(n)], pattern
    functions), if it cannot. *)

val eval : t -> float array -> float
(** Evaluate with one value per parameter. Raises [Invalid_argument] when
    the count is wrong or the function is {!unsupported}. *)

val eval3 : t -> float -> float -> float -> float
(** [eval3 f] checks once that [f] takes 3 parameters and is supported,
    then returns an evaluator (for isosurfaces and function patterns;
    safe to call from several domains: each call has its own slots).
    Raises [Invalid_argument]. *)
