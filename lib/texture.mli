(** Textures: a stack of layers, the top layer first (POV-Ray's layered
    textures: several [texture { }] on one object, the last one written on
    top). A layer is plain (pigment, normal, finish) or patterned
    ([texture { gradient x texture_map { [0 T1] [1 T2] } }] or
    [texture { checker texture { T1 } texture { T2 } }]): then the
    textures around the pattern's value are shaded and blended. *)

type layer = {
  pigment : Pigment.t;
  normal : Normal.t option;
  finish : Finish.t;
  tmap : tmap option;  (** [Some]: a patterned layer; the other fields are unused *)
  uv_texture : bool;
      (** made by [texture { uv_mapping ... }], which POV-Ray counts a
          patterned texture (see {!layering}) *)
}

and tmap = {
  pattern : Pattern.t;  (** unused by an average *)
  entries : (float * t) array;
      (** by value; for block patterns, one per cell; for an average, the
          weights (summing to 1). As in POV-Ray 3.7, they are taken at
          the point the pattern is evaluated at, in its space (its
          transformations, warps and turbulence applied; an average's at
          the point in its space): their own transformations are relative
          to it, and their normals are perturbed in it (turned by
          [frame]). A blob's components' textures are taken at the point
          itself. See {!blend_m}. *)
  xform : Transform.t;  (** pattern space to world (to the blob's for a {!Field}) *)
  uv : bool;
      (** [uv_mapping]: the pattern taken at the surface's [<u, v, 0>]
          (see {!Pattern.uv_point}); later transformations leave it *)
  turns : bool;
      (** uv-mapped by [texture { uv_mapping ... }]: the transformations
          written after it turn the entries' normals (see {!uv}) *)
  frame : Transform.t;
      (** what turns the entries' normals into the space they are
          perturbed in: [xform], and for a uv-mapped map that [turns] the
          transformations written after it too; unused by a {!Field} *)
  kind : kind;
}

(** How the entries are picked and weighed *)
and kind =
  | Map  (** by the pattern's value: one entry, or the two around it *)
  | Average
      (** POV-Ray's [texture { average texture_map { [w T] ... } }]: every
          entry shaded, the results weighted *)
  | Field of { blob : Blob.t; cut : float }
      (** a blob's components' own textures (entry [i] for component [i],
          the pattern unused): each component whose field is not zero at
          the point, weighed by its share of the fields there
          ({!Blob.weights}; [xform] is the blob's, object to world), as
          POV-Ray shades a blob whose components have textures; shares
          below [cut] (the scene's [adc_bailout]) are left out and the
          others kept as they are, as POV-Ray does *)

and t = layer list

val layer : Pigment.t -> Finish.t -> layer
(** No normal perturbation. *)

val plain : Pigment.t -> Finish.t -> t
val default : t
(** Black pigment, default finish: what objects without a texture get. *)

val patterned : Pattern.t -> (float * t) array -> layer
(** A texture_map layer (entries sorted by value), or a block pattern's
    textures (entry [i] for cell [i]). *)

val averaged : (float * t) array -> layer
(** An average of textures, the weights summing to 1 (the texture_map
    may also come later, by a modifier). *)

val blob_field : Blob.t -> cut:float -> Transform.t -> t array -> layer
(** [blob_field b ~cut xform textures]: the layer of a {!Field} (the
    textures by component, [xform] the blob's object to world). *)

type weights = { mutable k0 : float; mutable k1 : float }

type pick = private {
  mutable n : int;
  mutable t0 : t;
  mutable t1 : t;
  w : weights;
  mutable ws : Float.Array.t;
  mutable ix : int array;
  q : Vec3.m;
  tp : Vec3.m;
}
(** [n] textures with their weights (1 or 2 from a {!Map}; flat: storing
    them allocates nothing). Read them with {!entry} and {!weight}; [tp]
    is the point they are to be taken at. *)

val pick : unit -> pick

val blend_m : tmap -> Vec3.m -> pick -> unit
(** [blend_m m point pk]: the textures to shade at a world point with
    their weights (summing to 1, but for a {!Field}'s shares left out),
    one or the two around the pattern's value, or a blob's components'
    there, into [pk], allocating nothing (a pick grows once to a blob's
    number of components); for an average, only their number (read them
    with {!entry} and {!weight}). The point the textures are to be taken
    at into [pk.tp] (see {!tmap}: for a map, its pattern's point after
    its transformations, warps and turbulence, as POV-Ray 3.7's
    ComputeOneTextureColour passes it on); [point] may be [pk.tp]. *)

val entry : tmap -> pick -> int -> t
val weight : tmap -> pick -> int -> float
(** [entry m pk j] and [weight m pk j], [j < pk.n]: after {!blend_m}, the
    [j]th texture to shade and its weight. *)

val heaviest : tmap -> pick -> t
(** After {!blend_m}: the texture of largest weight (the first of equal
    ones; [[]] when there is none). *)

val uv : turns:bool -> t -> t
(** POV-Ray's [texture { uv_mapping ... }] ([turns]) and an object's
    [uv_mapping] (not [turns]): every pigment, normal and texture pattern
    of the texture's layers taken at the surface's [<u, v, 0>] (a
    patterned layer's entries follow its pattern, see {!tmap}); the
    transformations written after it do not move them, but with
    [turns] they turn its normals (see {!Normal.uv}). *)

val uv_texture : t -> t
(** [texture { uv_mapping T }]: {!uv} with [turns], marked as patterned
    for {!layering}. *)

val is_patterned : t -> bool
(** Some layer is patterned (see {!layering}): POV-Ray lets nothing be
    layered over it, a pigment, normal or finish written after it
    included. *)

val layering : above:t -> below:t -> string option
(** POV-Ray's refusal to layer textures where either side is patterned
    (a texture_map, a block pattern, material_map, average, or a
    texture-level uv_mapping): [Some message] ("cannot layer over a
    patterned texture" is checked first, as POV-Ray does), [None] when
    [above] may go on top of [below] (always, when [below] is empty). *)

val uses_uv : t -> bool
(** Some part of the texture is uv-mapped: the shader must set the
    surface's uv before evaluating it. *)

val blocks_light : t -> bool
(** Some unpatterned layer is opaque everywhere: no light passes. *)

val transform_layer : Transform.t -> layer -> layer
val transform : Transform.t -> t -> t
(** Move the patterns of a texture (a texture written before an object
    transform moves with the object): a plain layer's pigment and
    normal, a patterned layer's own pattern (its entries follow it, as in
    POV-Ray 3.7's Transform_Textures), a blob's components' textures. *)
