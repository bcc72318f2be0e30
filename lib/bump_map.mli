(** POV-Ray's [bump_map] (a normal read from an image), planar mapping
    ([map_type 0]): the image covers the unit square of the xy plane,
    repeated unless [once]. At a point, POV-Ray's rule (3.7,
    image.cpp's bump_map): heights [h1] at the point's pixel, [h2] one
    pixel left and one row down the image, [h3] one pixel right of that
    (rows and columns wrapping); the triangle (0, a h1, 0), (-1, a h2,
    1), (1, a h3, 1) ([a] the bump size) gives a normal [b], which is
    laid in a frame of the surface normal [n] (x along [n] x y, y along
    [n], z their cross product): [b.x x + b.y y - b.z z]. *)

type t

val make : w:int -> h:int -> once:bool -> interpolate:int -> by_index:bool -> Float.Array.t -> t
(** [make ~w ~h ~once ~interpolate ~by_index heights]: [heights] row by
    row, row 0 at the top of the image ([w * h] of them): the grey of
    each pixel's colour (POV-Ray's weights); [interpolate]: 0 none, 2
    bilinear, 4 normalised distance (POV-Ray's numbers); [by_index]:
    [use_index] was asked of this image without a palette, where POV-Ray
    interpolating reads an index 0 wherever its corner weights sum to
    less than 1 (no relief where all three samples do; modelled on
    POV-Ray's arithmetic, it brings such a render from 39.7 to 46.8 dB
    of POV-Ray's: some samples still round the other way).
    Raises [Invalid_argument] on a size mismatch or another
    interpolation. *)

val grey : float -> float -> float -> float
(** POV-Ray's grey of a colour: 0.297 r + 0.589 g + 0.114 b. *)

val tilt : t -> float -> Vec3.m -> Vec3.m -> Vec3.m -> unit
(** [tilt b amount q n out]: the bumped normal at [q] (pattern space) for
    the unit normal [n] (pattern space), into [out], not normalised; [n]
    itself where the image is not ([once], off the square). Allocates
    nothing. *)

val pixel : w:int -> h:int -> once:bool -> float -> float -> int
(** [pixel ~w ~h ~once x y]: the pixel (row by row from the top, [row *
    w + column]) of a [w] x [h] image that POV-Ray's planar mapping
    ([map_type 0], no interpolation) reads at [(x, y)], or -1 off the
    image ([once]). *)
