(** Bounding volume hierarchies over primitives given only by their
    axis-aligned boxes: a binned SAH build ({!Sah}), flattened depth first (a node's
    first child follows it) into one float32 array, 32 bytes per node (box
    rounded outward, and links), so a node visit touches one cache line.
    At most 2^23 primitives. The primitives themselves stay with the caller: a
    query calls back with primitive indices.

    Memory: 32 bytes per node (at most [2n - 1] nodes, about [n/2] with
    leaves of ~4), plus 8 bytes per primitive for the index permutation;
    while it runs, the build also holds copies of the boxes and costs in
    its permutation's order (56 bytes a primitive). *)

type t

val build :
  ?leaf_size:int -> ?node_cost:float -> ?cost:Float.Array.t -> ?par:(int -> (int -> unit) -> unit) ->
  Float.Array.t -> t
(** [build boxes]: [boxes] holds 6 floats per primitive (min x, y, z, max
    x, y, z). Primitives with empty or non-finite boxes must not be given.
    A node of at most [leaf_size] primitives (default 4) becomes a leaf
    when the surface area heuristic finds that testing them all costs no
    more than splitting it: [cost.(i)] is primitive i's test (default 1),
    [node_cost] a node's walk in the same unit (default 1; a node's cost
    is summed bin by bin, exactly for whole-number costs). With [par]
    (which runs [f 0] ... [f (n-1)] in any order or at once: see
    {!Render.parallel}), trees of at least 2^14 primitives are built by
    tasks of up to n/16 primitives below a top built first: the same tree,
    node for node, as without. *)

val size : t -> int
(** Number of primitives. *)

val nodes : t -> int

val bytes : t -> int
(** Memory held: 32 bytes per node (float32 boxes), 8 per primitive. *)

val bounds : t -> (Vec3.t * Vec3.t) option
(** The root box; [None] when there are no primitives. *)

val nearest : t -> Ray.t -> float -> Hit.t -> (int -> unit) -> unit
(** [nearest b ray tmin h f] calls [f i] for each primitive [i] whose leaf
    box meets the ray within [(tmin, h.t)], nearer boxes first; [f] is
    expected to lower [h.t] when it finds a closer hit, which prunes the
    rest of the walk. Allocates (a closure, a ray copy): {!nearest_s} is
    the allocation-free form. *)

val iter : t -> Ray.t -> float -> float -> (int -> bool) -> bool
(** [iter b ray tmin tmax f] calls [f i] for primitives whose leaf box meets
    the ray within [(tmin, tmax)], in no particular order, until [f]
    returns [false]; then returns [false]. *)

val nearest_s :
  t -> Ray.scratch -> float -> Hit.t -> 'a -> 'b -> ('a -> 'b -> Ray.scratch -> float -> Hit.t -> int -> bool) -> bool
(** [nearest_s b ray tmin h c1 c2 f]: as {!nearest}, calling [f c1 c2 ray
    tmin h i], which says whether it found a hit; true when some call did.
    With [f] a closed (top-level) function and the contexts [c1], [c2]
    already built, the walk allocates nothing: its stack is a per-domain
    array shared with nested walks started from [f]. *)

val iter_s :
  t -> Ray.scratch -> float -> 'a -> 'b -> ('a -> 'b -> Ray.scratch -> float -> int -> bool) -> bool
(** [iter_s b ray tmin c1 c2 f]: as {!iter} within [(tmin, ray.far)],
    calling [f c1 c2 ray tmin i]; allocation-free like {!nearest_s} (the
    far end is read from the ray: a distance computed per ray and passed as
    an argument would be boxed). *)

type stack
(** A domain's traversal stack, shared by the walks nested on it. *)

val stack : unit -> stack
(** The calling domain's stack (a lookup: a caller that walks often
    keeps it). *)

val nearest_st :
  stack -> t -> Ray.scratch -> float -> Hit.t -> 'a -> 'b -> ('a -> 'b -> Ray.scratch -> float -> Hit.t -> int -> bool) ->
  bool
(** {!nearest_s} on the calling domain's [stack], kept by the caller. *)

val iter_st : stack -> t -> Ray.scratch -> float -> 'a -> 'b -> ('a -> 'b -> Ray.scratch -> float -> int -> bool) -> bool
(** {!iter_s} on the calling domain's [stack], kept by the caller. *)

val renumber : t -> t * int array
(** [renumber b] is [(b', order)]: the same tree calling back with
    positions in leaf order, [order.(i)] being the primitive that position
    [i] stands for. Storing primitives in that order keeps the ones a leaf
    visits next to each other in memory. *)
