(** POV-Ray 3.7's [height_field]: a grid of heights over the unit square,
    x and z in [0, 1], height y in [0, 1), each cell cut into two
    triangles. Heights are POV-Ray's 16-bit values (0 .. 65535, y = value /
    65536). An image of [w] x [h] pixels gives [w] x [h] grid points: pixel
    column i at x = i / (w - 1), the image's top row at z = 1 and its bottom
    row at z = 0. Cell (i, j) is cut along the diagonal from (i + 1, j) to
    (i, j + 1): one triangle holds the corner (i, j), the other (i + 1, j +
    1) (hfield.cpp, checked with povray's trace()). [water_level] cuts the
    surface away below it. [smooth]: the normal is the bilinear blend of
    the four corners' normals (each the mean of the four fan triangles
    around a grid point, stored as POV-Ray stores them, in 16-bit
    integers), blended after the object's transform as POV-Ray does. The
    region under the surface is inside. *)

type t

val make : width:int -> depth:int -> heights:int array -> smooth:bool -> water:float -> t
(** [heights]: [width * depth] values in 0 .. 65535, row by row from the
    image's top row (z = 1) to its bottom row (z = 0). [water] is the
    water level on the 0..1 scale. Requires [width >= 2] and [depth >= 2]. *)

val place : t -> Transform.t -> t
(** The same field knowing its object's world transform (for [smooth]
    normals, which POV-Ray blends in world space). *)

val width : t -> int
val depth : t -> int
val smooth : t -> bool

val height : t -> int -> int -> float
(** [height f i j]: the raw value (0 .. 65535) at grid column [i] (x) and
    row [j] (z = j / (depth - 1)). *)

val hit_s : t -> Ray.scratch -> float -> Hit.t -> bool
(** Nearest crossing in [(tmin, h.t)] by a walk over the cells the ray
    crosses inside the field's box; allocates nothing. [h.id] holds the
    cell and triangle. *)

val normal_into : t -> Vec3.m -> Hit.t -> Vec3.m -> unit
(** Unit object-space normal at a point of a hit found by {!hit_s}. *)

val inside : t -> float -> float -> float -> bool
(** POV-Ray's test: below the surface (or the water level) within the
    field's square and under its top. *)

val bounds : t -> Vec3.t * Vec3.t

val surface : t -> float -> float -> float
(** [surface f x z]: the surface's height (object units) above a point
    of the unit square, by the triangle that holds it. *)
