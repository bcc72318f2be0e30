(** POV-Ray's [polygon]: flat closed outlines in one plane. A sub-outline
    ends where it comes back to its first point; the next point starts
    another. A point of the plane is on the surface where a ray from it
    crosses the outlines an odd number of times (so an outline inside
    another cuts a hole). No inside: like a triangle, a polygon is not a
    solid. *)

type t

val make : Vec3.t array -> (t * bool, string) result
(** The points as written; [Ok (p, closed)], [closed] false when the last
    outline did not come back to its start (then it is closed here, as
    POV-Ray does with a warning). [Error] when the points are fewer than
    3, lie on one line, or not in one plane. *)

val hit_s : t -> Ray.scratch -> float -> Hit.t -> bool
val normal : t -> Vec3.t
(** The plane's unit normal (its side as the points turn, counter-clockwise
    seen from where it points). *)

val point : t -> Vec3.t
(** The first point. *)

val bounds : t -> Vec3.t * Vec3.t
val edges : t -> int
