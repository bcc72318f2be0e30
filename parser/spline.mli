(** POV-Ray's splines: [linear_spline] (the default), [quadratic_spline],
    [cubic_spline] (Catmull-Rom) and [natural_spline], with POV-Ray 3.7's
    formulas and end rules (no extrapolation: the end values outside the
    range; lower orders when there are too few points). *)

type kind = Linear | Quadratic | Cubic | Natural

type t

val empty : kind -> t
val kind_of_name : string -> kind option
(** ["linear_spline"] -> [Linear], ... *)

val with_kind : t -> kind -> t
val length : t -> int

val add : t -> float -> terms:int -> float array -> t
(** [add s p ~terms v]: the entry (p, v) ([v] up to 5 components, [terms]
    of them meaningful); a parameter already present is replaced. *)

val eval : ?kind:kind -> t -> float -> float array
(** The value at a parameter, with [max 2 terms] components, optionally
    with another interpolation. Raises [Invalid_argument] on an empty
    spline. *)

type fn
(** A spline made ready for calls at render time, [function { spline {
    ... } }]: its kind fixed, a natural spline's coefficients computed
    once. *)

val prepare : t -> fn
(** Raises [Invalid_argument] on an empty spline. *)

val terms : fn -> int
(** The number of components of its values ({!eval}'s length). *)

val component_into : fn -> float array -> int -> int -> float array -> int -> unit
(** [component_into f src i k dst j]: component [k] (below 5) of the
    value at the parameter [src.(i)] into [dst.(j)], [0.] from {!terms}
    on; the same bits as {!eval}'s, nothing allocated. *)

val value : fn -> float -> float array
(** The value at a parameter, {!eval}'s, from {!component_into}. *)
