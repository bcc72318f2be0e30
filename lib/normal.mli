(** Normal perturbation ([normal { bumps 0.5 scale 0.2 }]): the surface
    normal is tilted by the gradient of a pattern. camlray computes the
    gradient by central differences of the pattern value (POV-Ray uses
    pattern-specific formulas), so bump shapes resemble POV-Ray's. *)

type t = { pattern : Pattern.t; amount : float; xform : Transform.t }

val make : Pattern.kind -> float -> t
val transform : Transform.t -> t -> t

val perturb : t -> Vec3.t -> Vec3.t -> Vec3.t
(** [perturb nm point n]: the perturbed unit normal at a world point. *)
