(** Three-component float vectors (points, directions, normals), stored flat
    by OCaml as an all-float record. POV-Ray's left-handed frame: +x right,
    +y up, +z into the screen. *)

type t = { x : float; y : float; z : float }

val make : float -> float -> float -> t
val zero : t
val one : t
val unit_x : t
val unit_y : t
val unit_z : t
val add : t -> t -> t
val sub : t -> t -> t
val neg : t -> t

val mul : t -> t -> t
(** Component-wise product. *)

val div : t -> t -> t
(** Component-wise quotient. *)

val scale : float -> t -> t
val madd : t -> float -> t -> t
(** [madd a k b] is [a + k b]. *)

val dot : t -> t -> float
val cross : t -> t -> t
(** The usual formula: [cross unit_x unit_y = unit_z]. *)

val length : t -> float
val length2 : t -> float

val normalize : t -> t
(** Unit vector in the same direction; the zero vector stays zero. *)

val dist : t -> t -> float
val min : t -> t -> t
val max : t -> t -> t
val get : t -> int -> float
(** [get v 0] is [v.x], 1 is [v.y], 2 is [v.z]. *)

val lerp : t -> t -> float -> t
val is_finite : t -> bool
val max_component : t -> float
val to_string : t -> string

(** A vector written in place, stored flat: the shading code keeps the
    points, normals and directions of each nesting level in these, per
    domain, so that a ray allocates none. *)
type m = { mutable mx : float; mutable my : float; mutable mz : float }

val m : unit -> m
(** A new one, zero. *)

val set : m -> float -> float -> float -> unit
val load : m -> t -> unit
val of_m : m -> t

val dot_m : m -> m -> float
(** {!dot} of two vectors written in place. *)

val inv_len : float -> float -> float -> float
(** [inv_len x y z]: the factor {!normalize} scales [(x, y, z)] by, [1 /
    |(x, y, z)|] (1 for the zero vector): each component times it is
    that of the unit vector, the same arithmetic, without making the
    vector (one square root for the three). *)

val normalize_m : m -> unit
(** {!normalize} in place (the same arithmetic). *)
