(** POV-Ray 3.7's [tiling N] pattern: 27 tilings of the xz plane (y does
    not matter). Tiling [n] has {!bands}[ n] kinds of tile; kind [i]
    takes the band [[i/k, (i+1)/k]] of the value, and within a tile the
    value grows from its inside (its centre, or a flat core) to its border,
    so a colour map with a thin band at the top of each band draws the
    grout. The layouts, sizes, orientations and bands are POV-Ray's
    (measured: its values at random points, test_tiling; its renders of
    the 27 template pigments, and scenes/whitted-extra/tiling.pov, are
    identical to camlray's):

    - 1 squares (side 1), 2 hexagons, 3 triangles (up, down), 4 lozenges,
      5 rhombs of three orientations, 6 rectangles 2 x 1 in a staircase,
      7 squares and octagons, 8 triangles and rows of squares, 9
      triangles and hexagons, 10 squares in offset rows, 11 and 12 a
      square with rectangles turning around it (one way, both ways), 13
      and 14 squares with hexagons pointed at both ends between them
      (3 bands, or 5: the hexagons by their side of the square), 15 squares of sides 1 and 2, 16 and 17 hexagons, squares and
      triangles (3 or 6 bands), 18 rectangles in a basket weave, 19 and 20
      hexagons among triangles (right- and left-handed), 21 squares and
      triangles (snub square), 22 dodecagons and triangles, 23 and 24
      dodecagons, hexagons and squares (3 or 5 bands);
    - 25 Penrose's P1 (pentagons of three kinds, stars, boats, diamonds),
      26 P2 (darts and kites), 27 P3 (wide and narrow rhombs), around the
      origin, not periodic; 1 at the origin itself. *)

type result = { mutable v : float }
(** Where a tiling leaves its value (a flat record: a float returned
    would be boxed). *)

val eval : int -> Vec3.m -> result -> unit
(** [eval n p r]: tiling [n] at [p] (its x and z), into [r.v], in
    [[0, 1]] (tiling 15's large squares reach 1.00000001, POV-Ray's
    margin; tiling 12 gives up to 7/3 on the lines where its folded
    coordinates are exactly 3, as POV-Ray). Allocates nothing. Raises [Invalid_argument] unless [n] is
    1 to 27. *)

val count : int
(** 27 *)

val bands : int -> int
(** The number of kinds of tile of a tiling (the bands of its value):
    1, 2, 3, 5 or 6. *)
