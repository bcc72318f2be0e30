(** Images read as a number a pixel, through POV-Ray's image mappings:
    the heights of a [bump_map], the values of an [image_pattern], the
    pixels a [material_map] picks textures by. The mapping is POV-Ray's
    map_pos (3.7.0, imageutil.cpp): planar ([map_type 0], and every
    number but 1, 2 and 5: the image covers the unit square of the xy
    plane), spherical (1), cylindrical (2) or torus (5) (see {!make}),
    repeated unless [once]; no interpolation, bilinear or normalised
    distance.

    A bump map's normal is POV-Ray's rule (3.7, image.cpp's bump_map):
    heights [h1] at the point's pixel, [h2] one
    pixel left and one row down the image, [h3] one pixel right of that
    (rows and columns wrapping); the triangle (0, a h1, 0), (-1, a h2,
    1), (1, a h3, 1) ([a] the bump size) gives a normal [b], which is
    laid in a frame of the surface normal [n] (x along [n] x y, y along
    [n], z their cross product): [b.x x + b.y y - b.z z]. *)

type t

val make : ?map_type:int -> w:int -> h:int -> once:bool -> interpolate:int -> by_index:bool -> Float.Array.t -> t
(** [make ~w ~h ~once ~interpolate ~by_index heights]: [heights] row by
    row, row 0 at the top of the image ([w * h] of them): for a bump
    map the grey of each pixel's colour (POV-Ray's weights);
    [interpolate]: 0 none, 2
    bilinear, 4 normalised distance (POV-Ray's numbers); [by_index]:
    [use_index] was asked of this image without a palette, where POV-Ray
    interpolating reads an index 0 wherever its corner weights sum to
    less than 1 (no relief where all three samples do; modelled on
    POV-Ray's arithmetic, it brings such a render from 39.7 to 46.8 dB
    of POV-Ray's: some samples still round the other way).
    [map_type] (default 0): 1 wraps the image round the unit sphere
    (columns the longitude from +x towards +z, rows the latitude, the
    top row at +y), 2 round the cylinder about y (the longitude; rows
    the height y, the image from 0 to 1), 5 round a torus of major
    radius 1 about y (the longitude; rows the angle about the tube),
    any other number is planar, as in POV-Ray.
    Raises [Invalid_argument] on a size mismatch or another
    interpolation. *)

val grey : float -> float -> float -> float
(** POV-Ray's grey of a colour: 0.297 r + 0.589 g + 0.114 b. *)

val tilt : t -> float -> Vec3.m -> Vec3.m -> Vec3.m -> unit
(** [tilt b amount q n out]: the bumped normal at [q] (pattern space) for
    the unit normal [n] (pattern space), into [out], not normalised; [n]
    itself where the image is not ([once], off the square). Allocates
    nothing. *)

val pixel : w:int -> h:int -> once:bool -> Vec3.m -> int
(** [pixel ~w ~h ~once q]: the pixel (row by row from the top, [row *
    w + column]) of a [w] x [h] image that POV-Ray's planar mapping
    ([map_type 0], no interpolation) reads at [q]'s x and y, or -1 off
    the image ([once]). Allocates nothing. *)

val value : t -> Vec3.m -> float
(** [value b q]: the image's number at [q] (pattern space): the pixel's,
    or its neighbours' interpolated, kept within [[0, 1]]; 0 off the
    image ([once], or a point the mapping has no place for: the centre
    of the sphere, the axis of the cylinder or the torus, the torus's
    core circle), as POV-Ray's image_pattern. Inlined where it is
    called: it allocates nothing. *)

val weight : int -> float -> float -> int -> float
(** [weight interpolate p q k]: POV-Ray's weight of corner [k] (0 the
    texel at the point's integer coordinates, 1 left, 2 up, 3 up-left)
    for the fractions [p], [q] past it: bilinear for 2, normalized
    inverse square distance otherwise. Inlined: nothing boxed. *)

val locate : w:int -> h:int -> once:bool -> map_type:int -> Vec3.m -> Vec3.m -> bool
(** [locate ~w ~h ~once ~map_type q c]: POV-Ray's map_pos (imageutil.cpp)
    for a [w] x [h] image: the point [q] (pattern space) taken to the
    image's column [c.mx] and row from the top [c.my], in [0, w) and
    [0, h), its tiny offset included; false off the image ([once], or a
    point the mapping leaves out). Image maps, image patterns and bump
    maps all place points by it. Allocates nothing. *)
