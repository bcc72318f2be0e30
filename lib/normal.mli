(** Normal perturbation ([normal { bumps 0.5 scale 0.2 }]), as POV-Ray
    3.7's Perturb_Normal (normal.cpp): the surface normal is taken to
    pattern space, moved there and brought back. bumps, dents,
    wrinkles, ripples, waves and quilted move it by POV-Ray's formulas of
    their own (over POV-Ray's noise, {!Noise.dnoise} and {!Noise.noise};
    ripples' and waves' sources {!Pattern.waves}); every other pattern by
    its slope, sampled on POV-Ray's tetrahedron around the point (warped
    once, at the centre) with POV-Ray's arithmetic (a tilt of amount/10
    per unit of slope). The amount, accuracy, frequency and phase in
    single precision, as POV-Ray keeps them: POV-Ray's pictures to the
    16-bit step (test suite waves). *)

type t = {
  pattern : Pattern.t;
  amount : float;
  xform : Transform.t;
  slope : Float.Array.t;
      (** POV-Ray's [slope_map]: (value, height, slope) triples by rising
          value, the pattern's value taken to a height by Hermite cubics
          between them; empty: none (the height is the value). Unused by
          the patterns with formulas of their own, as in POV-Ray. *)
  accuracy : float;  (** the distance of the samples the slope is taken from (0.02) *)
  map : map;
}

(** A normal made of other normals (POV-Ray's [normal_map], [average] and
    block patterns' normal lists): the entries perturb the normal in this
    normal's pattern space (their transforms are relative to it), their
    unit results are weighted, summed, brought back and normalised. *)
and map =
  | Leaf  (** the pattern's own slope *)
  | Blend of (float * t) array
      (** [normal_map]: entries by rising value; the two around the
          pattern's value weighted 1 - k and k *)
  | Average of (float * t) array  (** [average]: weights summing to 1; the pattern is unused *)
  | Cells of t array  (** checker, hexagon, brick, object: the cell's normal *)
  | Image of Bump_map.t
      (** [bump_map]: the normal tilted by the image's height differences
          ({!Bump_map.tilt}, [amount] its bump size); the pattern is
          unused *)
  | Facets of Facets.t
      (** [facets]: the normal snapped or tilted by POV-Ray's facets
          formula ({!Facets.tilt_m}); of the pattern only the warps and
          turbulence are used (on the point), and the amount is not *)
  | Uv of { entry : t; turns : bool }
      (** POV-Ray's [uv_mapping] (see {!uv}): [entry] perturbs the normal
          at the surface's [<u, v, 0>] ({!Pattern.uv_point}); the
          pattern, amount and slope of this normal are unused, its
          transform is the frame the normal is perturbed in *)

val default_accuracy : float
(** POV-Ray's 0.02. *)

val make : Pattern.kind -> float -> t
val transform : Transform.t -> t -> t
(** Applied after the normal's transform (a map's entries, relative to
    it, follow). A [Uv] normal that does not [turns] is left as it is. *)

val uv : turns:bool -> t -> t
(** POV-Ray 3.7's [uv_mapping] of a normal (measured on probes): the
    normal's pattern (through its own transform) is taken at the
    surface's [<u, v, 0>] instead of the point, and its slope tilts the
    surface's world normal as if uv space were world space (no tangent
    frame: a pattern's slope along u tilts the normal along world x).
    The transformations written after it: none apply when [turns] is
    false ([normal { uv_mapping ... }], an object's [uv_mapping]); with
    [turns] ([texture { uv_mapping ... }]) they turn the normal as a
    pattern's transform does (into their space, perturbed, back) but do
    not move the point. A normal already uv-mapped is kept (turning if
    either does). *)

val uses_uv : t -> bool
(** Some part of the normal is uv-mapped: the shader must set the
    surface's uv before perturbing with it. *)

val perturb_m : t -> Vec3.m -> Vec3.m -> Vec3.m -> unit
(** [perturb_m nm point n out]: the perturbed unit normal at a world
    point, into [out] (not [n]), allocating nothing (per domain, nested
    maps' work is kept by depth). *)

val perturb_through : t -> Vec3.m -> Vec3.m -> Transform.t array -> int -> Vec3.m -> Vec3.m -> unit
(** [perturb_through nm point n chain nchain tn out]: [perturb_m] in the
    frames of the texture maps above the layer (the first [nchain] of
    [chain], innermost last, as POV-Ray's Warp_Normal / UnWarp_Normal):
    [n] turned into them, perturbed, turned back, into [out]; [tn] is
    scratch. Allocates nothing. *)

val slope_height : Float.Array.t -> float -> float
(** [slope_height map v]: the height a slope map gives the value [v]:
    the first entry's height at or below its value, the last's past its
    value, else the Hermite cubic between the two entries around [v],
    their heights and slopes at its ends (POV-Ray's rule). *)
