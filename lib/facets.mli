(** POV-Ray's [facets] normal ([normal { facets [coords C] [size S]
    [metric M] }]), a normal of its own (it has no value as a pattern).
    POV-Ray's formula (normal.cpp) over crackle's feature points
    ({!Pattern.feature_point}, for the cube below each point less 1e-10,
    as POV-Ray's PickInCube) and POV-Ray's DNoise ({!Noise.dnoise}): the
    facets lie where POV-Ray's do when crackle's points are POV-Ray's.

    Without [coords] (or with [coords 0]): the unit normal, scaled by
    1/[size], picks the nearest feature point, and that point (a position,
    read as a direction) is the new normal: normals are snapped to a
    perturbed grid of directions, so a curved surface shows flat facets
    (a flat one shows none). With [coords C]: the point, scaled by
    1/[size], picks the nearest feature point (the cells of crackle), and
    the normal is tilted by [C] times the part of the noise at that
    feature point perpendicular to it: flat facets on any surface.

    The nearest is searched among the points of the point's cube and 80
    neighbours (POV-Ray's: the 3x3x3 block and the cubes two away along
    one axis), in the metric: 2 (default) Euclidean, 1 the sum of the
    differences (signed, as POV-Ray computes it), else the sum of their
    magnitudes to the power [metric]. *)

type t = { size : float; coords : float; metric : float }

val default : t
(** POV-Ray's defaults: size 0.1, coords 0 (off), metric 2. *)

val tilt_m : t -> Vec3.m -> Vec3.m -> Vec3.m -> unit
(** [tilt_m f q n out]: in pattern space, at the point [q] (warped) with
    the unit normal [n], the new normal into [out] (not unit: the caller
    brings it back to world space and normalises it). Allocates nothing;
    per domain, the last cube's feature points are kept. *)
