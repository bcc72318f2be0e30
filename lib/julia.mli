(** POV-Ray's [julia_fractal] (quaternion algebra, [sqr] and [cube]):
    the points [<x, y, z, 0>] whose iteration [q <- q^2 + c] (or
    [q^3 + c]) stays within the radius [1 + |c|] for [max_iteration - 1]
    steps, as POV-Ray 3.7 decides (found by fitting its [trace()] hits:
    that radius and that count reproduce them to 5e-8). A ray is walked
    from where it enters the sphere of that radius in steps of
    [1 / precision], each change between inside and outside bisected to
    1e-7; the normal is the gradient of [|q|^2] after [max_iteration]
    steps (POV-Ray's normals to 1e-7). *)

type t

val make : c:float array -> cube:bool -> max_iteration:int -> precision:float -> (t, string) result
(** [c] has 4 components; [max_iteration] at least 1, [precision]
    positive. *)

val inside : t -> float -> float -> float -> bool
val hit_s : t -> Ray.scratch -> float -> Hit.t -> bool
val normal_into : t -> Vec3.m -> Vec3.m -> unit
val bounds : t -> Vec3.t * Vec3.t
