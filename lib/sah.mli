(** The binned surface-area-heuristic build of {!Bvh}'s trees, over
    primitives given only by their axis-aligned boxes, flattened depth
    first (a node's first child follows it) into one float32 array of 32
    bytes a node (the box rounded outward, and links), so that a node
    visit touches one cache line. While it runs the build holds copies of
    the boxes and costs in its permutation's order (56 bytes a
    primitive). *)

type f32 = (float, Bigarray.float32_elt, Bigarray.c_layout) Bigarray.Array1.t

type tree = {
  nodes : f32;  (** 8 floats a node: box (min x, y, z, max x, y, z); a leaf's first position in [prims] and count (> 0), or an inner node's second child and -(axis+1) *)
  prims : int array;  (** the primitives in leaf order *)
  depth : int;  (** at least the number of nodes on any root-to-leaf path *)
}

val max_prims : int
(** 2^23: node indices and offsets are stored in float32. *)

val build :
  ?leaf_size:int -> ?node_cost:float -> ?cost:Float.Array.t -> ?par:(int -> (int -> unit) -> unit) ->
  Float.Array.t -> tree
(** As {!Bvh.build}. *)
