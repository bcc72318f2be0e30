(** Pattern functions of POV-Ray pigments and normals: a number in
    [[0, 1]] (or a cell index for the block patterns checker, hexagon,
    brick) for a point in pattern space. The exact patterns (checker,
    gradient, radial, onion, wood, marble, leopard, hexagon, brick) agree
    with POV-Ray 3.7's [function { pattern { ... } }] values; so do the
    noise patterns (bozo, spotted, bumps, dents, granite, wrinkles,
    agate, crackle, marble and wood with turbulence), in POV-Ray's noise
    ({!Noise}) and formulas (pattern.cpp), to 1e-15 (test_noise's
    pov_patterns). spiral1, spiral2, quilted and mandel follow POV-Ray's
    formulas (core/material/pattern.cpp); a function pattern's value is
    its function's, taken mod 1 above 1 as POV-Ray does. *)

type wave = Ramp | Triangle | Sine | Scallop | Cubic | Poly of float

type fractal = {
  iterations : int;  (** at least 1 *)
  exponent : int;  (** 2 to 33 *)
  exterior : int;  (** colouring of escaping points, 0 to 8 (default 1: iterations / max) *)
  efactor : float;  (** default 1 *)
  interior : int;  (** colouring of points that never escape, 0 to 6 (default 0: ifactor) *)
  ifactor : float;  (** default 1 *)
}
(** The mandel pattern's parameters ([mandel N exponent E interior T, F
    exterior T, F]). *)

type fn
(** A user function of x, y, z used as a pattern ([function { ... }]):
    compiled code over an array of float slots, one array per domain. *)

val fn : slots:int -> result:int -> (float array -> unit) -> fn
(** [fn ~slots ~result run]: [run s] reads x, y, z from [s.(0)],
    [s.(1)], [s.(2)] of an array of [slots] floats ([slots >= 3], [result
    < slots]) and leaves the function's value in [s.(result)]. Each
    domain runs it on an array of its own, so [run] may be called from
    several domains at once; it should not allocate (the pattern then
    allocates nothing). A function must not evaluate, while it runs,
    the same [fn] again (functions are defined before they are used, so
    this holds for functions of the scene language). *)

type inside
(** An object's inside test at a point written in place (the object
    pattern's): a closure made once, which allocates nothing when asked. *)

val inside : (Vec3.m -> bool) -> inside
(** [inside test]: [test p] says whether [p] (pattern space, which is the
    object's world space) is inside the object. [test] may be called from
    several domains at once and must not allocate. *)

type crackle = { form : Vec3.t; metric : float; offset : float; solid : bool }
(** POV-Ray's crackle parameters: [form] weighs the distances to the
    three nearest feature points, [metric] is the exponent of the
    distance's norm, [offset] is added; [solid] gives each cell one
    value. *)

val crackle_default : crackle
(** form <-1, 1, 0>, metric 2, offset 0, not solid. *)

val crackle_cubes : int array
(** The 81 cubes crackle (and facets) look in around the point's own, as
    x, y, z offsets three apiece in POV-Ray's order: every cube within two
    on each axis, at most one axis two away. *)

val feature_point : float -> float -> float -> Vec3.m -> unit
(** [feature_point cx cy cz out]: crackle's feature point of the unit
    cube whose lowest corner is [(cx, cy, cz)] (whole numbers), into
    [out]: POV-Ray's (PickInCube): the corner plus three of POV-Ray's
    pattern random numbers ({!Cells.values}) from the slot the cube
    hashes to ({!Cells.index}) on. *)

type kind =
  | Checker
  | Hexagon
  | Brick of { size : Vec3.t; mortar : float }
  | Gradient of Vec3.t  (** normalised by {!gradient} *)
  | Radial
  | Onion
  | Planar  (** 1 - |y|, 0 beyond 1 *)
  | Spherical  (** 1 - |p|, 0 beyond 1 *)
  | Boxed  (** 1 - max(|x|, |y|, |z|), 0 beyond 1 *)
  | Cylindrical  (** 1 - sqrt(x^2 + z^2), 0 beyond 1 *)
  | Wood
  | Marble
  | Leopard
  | Bozo
  | Spotted  (** bozo's noise, black to white *)
  | Bumps  (** bozo's noise, black to white *)
  | Dents
  | Granite
  | Agate of float  (** agate_turb *)
  | Ripples
  | Waves
  | Wrinkles
  | Crackle of crackle  (** F2 - F1 cellular noise by default (POV-Ray's feature points and formulas) *)
  | Spiral1 of int
      (** arms: z + r + arms phi / 2 pi around the z axis (triangle wave) *)
  | Spiral2 of int  (** arms: tri(spiral1's value) + tri(r) (triangle wave) *)
  | Quilted of { c0 : float; c1 : float }
      (** control0, control1: unit cells shaded by a cubic of the
          distance to their centre (frequency 0: no wrapping) *)
  | Mandel of fractal  (** the Mandelbrot set in the xy plane *)
  | Julia of { cr : float; ci : float; fractal : fractal }
      (** the Julia set of c = cr + i ci in the xy plane (z from the point) *)
  | Magnet of { formula : int; julia : bool; cr : float; ci : float; fractal : fractal }
      (** POV-Ray's [magnet 1|2 mandel|julia]: z <- ((z^2 + c - 1) / (2z + c -
          2))^2 (formula 1) or its cubic counterpart (2), from z = 0 with c
          the point (mandel) or from the point with c = cr + i ci (julia),
          until z comes within 0.01 of 1 or leaves |z| <= 100 (exterior) *)
  | Slope of { dir : Vec3.t; lo : float; hi : float; wdir : float; alt : Vec3.t; alo : float; ahi : float; walt : float }
      (** POV-Ray's [slope]: [0.5 + asin(n . dir) / pi] for the shaded
          surface's world normal [n] (see {!set_normal}; not turned by the
          pattern's transformations, as POV-Ray), taken from [[lo, hi]]
          to [[0, 1]], and the altitude [p . alt] from [[alo, ahi]],
          weighed [wdir] and [walt] (the lengths of the vectors written;
          [dir] and [alt] are unit) *)
  | Cells  (** one value in [[0, 1)] per unit cube, POV-Ray's ({!Cells}) *)
  | Tiling of int
      (** POV-Ray's [tiling N], N from 1 to 27 ({!Tiling}): tilings of the
          xz plane, each kind of tile a band of the value, growing
          towards the tile's border *)
  | Object of inside
      (** POV-Ray's [object] pattern: cell 1 inside the object, 0 outside
          (a block pattern of two cells) *)
  | Material of { w : int; h : int; once : bool; numbers : Bytes.t; count : int }
      (** POV-Ray's [material_map]: the number of the image's pixel
          under the point ({!Bump_map.pixel}; 0 off the image), a palette
          index or a red byte, one a pixel in [numbers]; above [count]
          taken mod [count], then at most [count - 1]: the cell of one of
          [count] textures *)
  | Function of fn
      (** [function { ... }]: the function at the point, mod 1 above 1
          (values below 0 are left to the frequency step, which takes
          them mod 1) *)
  | Density_file of density
      (** [density_file df3 "file" [interpolate 0|1]]: the voxels of the
          unit cube [[0, 1)^3], 0 outside *)
  | Image of Bump_map.t
      (** POV-Ray's [image_pattern]: the image's number under the point
          ({!Bump_map.value}: a pixel's grey, or its transparency, read
          when the scene is compiled; 0 off the image); frequency 0 by
          default, as in POV-Ray *)

and density = { nx : int; ny : int; nz : int; voxels : Float.Array.t; interpolate : int }
(** A df3 file's voxels, x fastest, each in [[0, 1]]; interpolation 0
    (the voxel's value) or 1 (trilinear, wrapping at the far faces, as
    POV-Ray 3.7 does). *)

val read_df3 : string -> density
(** The voxels of a df3 file (big-endian sizes x, y, z, then 1, 2 or 4
    byte values), interpolation 0. Raises [Failure] on a damaged file. *)

type turbulence = { amount : Vec3.t; octaves : int; omega : float; lambda : float }
(** A turbulence (classic or warp): [omega] and [lambda] as POV-Ray
    keeps them, in single precision ({!single}; the parser rounds them).
    Classic: marble takes x + amount.x Turbulence, wood the cycloidal of
    DTurbulence, agate and the spirals add the scalar Turbulence, the
    others are moved by DTurbulence times the amount (POV-Ray's). *)

(** POV-Ray's [warp { }]s, each acting on the point in the space of the
    transformations written before it. *)
type warp_kind =
  | Repeat of { axis : int; width : float; offset : Vec3.t; flip : Vec3.t }
      (** [repeat v]: the pattern's slab [0, width) along axis [axis]
          (0, 1, 2; [width] is [v]'s component there, sign kept) copied
          along it; each copy [k] moved by [k offset]; in odd copies the
          components whose [flip] is negative are mirrored (across the
          slab on the repeated axis) *)
  | Black_hole of {
      center : Vec3.t;
      radius : float;
      strength : float;
      falloff : float;
      inverse : bool;
      repeat : Vec3.t;
          (** positive components: a hole in every cell of that size,
              [center] from the cell's corner (the parser raises it to
              the radius and widens the cells as POV-Ray does) *)
      jitter : Vec3.t;
          (** [turbulence] of a repeated hole: each cell's centre moved by
              POV-Ray's warp random numbers (in [0, 1)) times this *)
    }
      (** points within [radius] of the hole pushed out of it (pulled in
          when [inverse]) by [strength (1 - d / radius)^falloff] of their
          distance [d], that share at most 1 (POV-Ray's clip) *)
  | Turbulence of turbulence  (** [warp { turbulence ... }] *)
  | Planar_map of { orient : Vec3.t; offset : float }
      (** [planar [orient, offset]]: (x, y, offset), turned so that the
          mapping's z goes along [orient] (a unit vector; z by default) *)
  | Spherical_map of { orient : Vec3.t; dist_exp : float }
      (** [spherical]: (longitude, latitude, distance) from the origin,
          longitude about y from +x towards +z in turns [0, 1), latitude
          from the south pole in half-turns [0, 1]; the two angles scaled
          by distance^[dist_exp] (not at 0), then turned as for [Planar_map] *)
  | Cylindrical_map of { orient : Vec3.t; dist_exp : float }
      (** [cylindrical]: (turns about y, y, distance from y), the turns
          scaled by distance^[dist_exp] (not at 0), turned as above *)
  | Toroidal_map of { orient : Vec3.t; dist_exp : float; major : float }
      (** [toroidal]: (turns about y, turns about the ring of radius
          [major], distance from that ring), both angles scaled by
          distance^[dist_exp] (not at 0), turned as above *)

type warp = { kind : warp_kind; into : Transform.t; back : Transform.t }
(** [back]: the transformations written before the warp; [into] their
    inverse, whose inverse (applied by [Transform.inv_point_m]) takes a
    point of pattern space into the space the warp was written in. *)

val warp : Transform.t -> warp_kind -> warp
(** [warp before k]: a warp written after the transformations [before]. *)

type t = {
  kind : kind;
  turbulence : turbulence option;
  frequency : float;
  phase : float;
  wave : wave option;  (** [None]: the pattern's default wave *)
  warps : warp array;
      (** in written order; applied last first to the point in pattern
          space, before the (classic) turbulence and the pattern *)
  noise_gen : int;
      (** the pattern's [noise_generator]: 1, 2 or 3; 0 when it names none
          (then the scene's, {!scene_noise_generator}) *)
}

val quilt_cubic : float -> float -> float -> float
(** [quilt_cubic t c0 c1]: quilted's scale of an offset of length [t] from
    its cell's centre (a cubic Bezier with inner controls [c0], [c1]). *)

val scene_noise_generator : int ref
(** The scene's [noise_generator] (2, POV-Ray 3.7's default, unless its
    [global_settings] name another), for patterns naming none: set by the
    compiler for the scene it compiles, only read while rendering. *)

val generator : t -> Noise.generator
(** The generator the pattern's noise uses. *)

val make : kind -> t
(** No turbulence, frequency 1 (quilted and image: 0), phase 0, default
    wave. *)

val mandel : int -> fractal
(** [mandel n]: [n] iterations, exponent 2, POV-Ray's default exterior
    (1, 1) and interior (0, 1). *)

val gradient : Vec3.t -> kind
val default_turbulence : Vec3.t -> turbulence
(** octaves 6, omega 0.5, lambda 2. *)

val is_block : kind -> bool
(** checker, hexagon, brick, object: the value is a cell index, used with a list
    of colours or pigments rather than a map. *)

val block_count : kind -> int
(** Number of cells: 2 (checker, brick, object), 3 (hexagon), a
    material map's count. *)

val value : t -> Vec3.t -> float
(** The pattern at a point of pattern space: turbulence warp, the raw
    pattern, then frequency, phase and wave shaping (block patterns:
    the cell index as a float, no shaping). As POV-Ray, frequency 0
    leaves the value unwrapped (only a negative one is taken mod 1). *)

type result = Tiling.result = { mutable v : float }

type work = { p : Vec3.m; d : Vec3.m; r : result; e : Vec3.m }
(** Where {!eval_m} works: the warped point, the turbulence, the value
    (in a flat record: storing a float into a record with other fields
    would allocate), and for marble and wood the warped point before
    their turbulence (see {!entries_point}). *)

val entries_point : t -> work -> Vec3.m
(** After {!eval_m} (or {!eval_at}): the point a map's entries are taken
    at, as POV-Ray 3.7 passes it on to them (Warp_EPoint's TPoint): the
    point in the pattern's space with its warps and turbulence applied
    ([w.p]); for marble and wood, which handle their turbulence
    themselves in POV-Ray, without the turbulence (measured: a marble
    pigment_map's checker entries are not turbulated, a gradient's
    are). The work's own vector: copy it before evaluating another
    pattern with the same work. *)

val work : unit -> work

val set_normal : Vec3.m -> unit
(** The unit normal (world space) of the surface being shaded, for the
    slope pattern; per domain, set by the shader before it evaluates a
    texture. *)

val set_uv : float -> float -> unit
(** [set_uv u v]: the surface coordinates of the point being shaded, per
    domain, set by the shader (when the object's texture is uv-mapped)
    before it evaluates a texture. *)

val uv_point : unit -> Vec3.m
(** The point [<u, v, 0>] last set by {!set_uv} on this domain (the
    domain's own vector: read it, never write it). *)

val cycloidal : float -> float
(** POV-Ray's [cycloidal] (texture.cpp): the sine of a value in turns,
    with POV-Ray's rounding (the fraction scaled by 50000 and back). *)

type waves = { count : int; src : Float.Array.t; freq : Float.Array.t }
(** The wave sources and frequencies of ripples and waves, POV-Ray 3.7's
    (texture.cpp's Initialize_Waves): [src] holds source [i]'s x, y, z
    at [3i .. 3i+2], DNoise at (i, 0, 0) normalised; [freq] its
    frequency, 0.01 + 0.000030518509476 times 15 bits of the C library's
    congruence from the seed -560851967. *)

val make_waves : int -> waves
(** [make_waves n]: the first [n] sources (n >= 1). *)

val set_number_of_waves : int -> unit
(** The scene's [number_of_waves] (10 unless its [global_settings] name
    another; below 1 taken as 1, as POV-Ray says it does): set by the
    compiler for the scene it compiles, only read while rendering. *)

val waves : unit -> waves
(** The scene's waves. *)

val warped_m : t -> Vec3.m -> work -> unit
(** [warped_m t q w]: the point [q] of pattern space with the pattern's
    warps and turbulence applied, into [w.p] (what {!eval_m} evaluates
    the raw pattern at). *)

val warp_in_place : t -> Vec3.m -> work -> unit
(** [warp_in_place t q w]: [q] moved by the pattern's warps and
    turbulence (nothing done when it has none), for what carries only
    warps (an image map, a bump map, an average); [w.p] is overwritten. *)

val eval_warped : t -> work -> unit
(** [eval_warped t w], after [warped_m t q w]: the rest of {!eval_m} (the
    raw pattern at [w.p], then the value's shaping), into [w.r.v]. A
    function pattern may evaluate other patterns meanwhile: what a
    caller keeps of [w] (the point for the entries) is read before. *)

val eval_m : t -> Vec3.m -> work -> unit
(** [eval_m t q w]: {!value} at a point written in place, into [w.r.v]
    (the same arithmetic), allocating nothing. *)

val eval_at : t -> Transform.t -> Vec3.m -> work -> float
(** [eval_at t xform point w]: {!eval_m} at a world point taken into the
    pattern's space by [xform]'s inverse; the value is also left in
    [w.r.v]. Inlined where it is called (its result is not boxed). *)

val around : (float * 'a) array -> float -> int
(** [around entries v], for entries sorted by value (at least one): 0
    when [v] is at or below the first entry's value, [n] when it is past
    the last one's, else the [i] in [1 .. n-1] such that entries [i-1]
    and [i] are around it. The search colour, pigment and texture maps
    share. *)

val checker_m : Vec3.m -> int
(** The checker pattern's value (0 or 1) at a point written in place, as
    {!value} gives it for [make Checker]. *)
