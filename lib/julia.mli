(** POV-Ray's [julia_fractal] (quaternion algebra with [sqr] and [cube],
    hypercomplex algebra with [sqr]):
    the points [<x, y, z, 0>] whose iteration [q <- q^2 + c] (or
    [q^3 + c]) stays within the radius [1 + |c|] for [max_iteration - 1]
    steps, as POV-Ray 3.7 decides (found by fitting its [trace()] hits:
    that radius and that count reproduce them to 5e-8). A ray is walked
    from where it enters the sphere of that radius in steps of
    [1 / precision], each change between inside and outside bisected to
    1e-7; the normal is the gradient of [|q|^2] after [max_iteration]
    steps (POV-Ray's normals to 1e-7). A hypercomplex fractal iterates
    POV-Ray's commutative algebra (i^2 = j^2 = -1, k^2 = 1) the same way. *)

type t

val make :
  c:float array -> hypercomplex:bool -> cube:bool -> max_iteration:int -> precision:float -> (t, string) result
(** [c] has 4 components; [max_iteration] at least 1, [precision]
    positive; [cube] only with the quaternion algebra. *)

val inside : t -> float -> float -> float -> bool
val hit_s : t -> Ray.scratch -> float -> Hit.t -> bool
val normal_into : t -> Vec3.m -> Vec3.m -> unit
val bounds : t -> Vec3.t * Vec3.t
