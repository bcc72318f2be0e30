(* Bounding volume hierarchies: the tree {!Sah} builds, and its walks.
   Node k is 8 single-precision floats at nodes.(8k .. 8k+7) (the layout
   is Sah's): its box, then for a leaf the first entry in [prims] and the
   primitive count (> 0), for an interior node the index of its second
   child (the first is k+1) and -(axis+1). *)
type f32 = Sah.f32

(* [prims] is empty when the tree calls back with the leaf positions
   themselves (after [renumber]): no indirection to read at every leaf *)
type t = { nodes : f32; prims : int array; n : int; depth : int }

let size b = b.n
let nodes b = Bigarray.Array1.dim b.nodes / 8
let nget (a : f32) i = Bigarray.Array1.unsafe_get a i

let bounds b =
  if Bigarray.Array1.dim b.nodes = 0 then None
  else
    let g = nget b.nodes in
    Some (Vec3.make (g 0) (g 1) (g 2), Vec3.make (g 3) (g 4) (g 5))

(* fmin/max call C (signbit) to order NaN and -0; boxes hold neither *)
let[@inline] fmin (a : float) b = if a < b then a else b
let[@inline] fmax (a : float) b = if a > b then a else b

let build ?leaf_size ?node_cost ?cost ?par boxes =
  let n = Float.Array.length boxes / 6 in
  let { Sah.nodes; prims; depth } = Sah.build ?leaf_size ?node_cost ?cost ?par boxes in
  { nodes; prims; n; depth }

(* Slab test against box k within (t0, t1). [sx] is 0 when the ray goes
   towards +x (it enters through the low plane, stored first) and 3 when it
   goes towards -x, likewise [sy], [sz]: no min/max per axis, which OCaml
   compiles to branches. *)
let[@inline] box_hit (nodes : f32) k sx sy sz ox oy oz ix iy iz t0 t1 =
  (* [+. 0.] unboxes the bounds: a branch choosing between a boxed and an
     unboxed float would box the result *)
  let t0 = t0 +. 0. and t1 = t1 +. 0. in
  let o = 8 * k in
  let nx = (nget nodes (o + sx) -. ox) *. ix and fx = (nget nodes (o + 3 - sx) -. ox) *. ix in
  let ny = (nget nodes (o + 1 + sy) -. oy) *. iy and fy = (nget nodes (o + 4 - sy) -. oy) *. iy in
  let nz = (nget nodes (o + 2 + sz) -. oz) *. iz and fz = (nget nodes (o + 5 - sz) -. oz) *. iz in
  let lo = fmax (fmax nx ny) (fmax nz t0) in
  let hi = fmin (fmin fx fy) (fmin fz t1) in
  lo <= hi

let[@inline] inv d = if d = 0. then 1e300 else 1. /. d

(* Traversal stacks: one growable int array per domain, shared by nested
   traversals (a union's BVH inside the scene's, a mesh's inside a
   union's), each using the slots above the one that called it. A
   traversal keeps the array it started with: when a nested one grows the
   stack, the outer one's slots stay valid in the old array. *)
type stack = { mutable slots : int array; mutable dist : Float.Array.t; mutable top : int }

let stack_key =
  Scratch.key (fun () -> { slots = Array.make 1024 0; dist = Float.Array.make 1024 0.; top = 0 })

let[@inline] reserve st n =
  let base = st.top in
  if base + n > Array.length st.slots then begin
    let a = Array.make (2 * (base + n)) 0 and d = Float.Array.make (2 * (base + n)) 0. in
    Array.blit st.slots 0 a 0 base;
    Float.Array.blit st.dist 0 d 0 base;
    st.slots <- a;
    st.dist <- d
  end;
  st.top <- base + n;
  base

(* Entry distance of the ray into box k within (t0, t1), or infinity. *)
let[@inline] box_entry (nodes : f32) k sx sy sz ox oy oz ix iy iz t0 t1 =
  let t0 = t0 +. 0. and t1 = t1 +. 0. in
  let o = 8 * k in
  let nx = (nget nodes (o + sx) -. ox) *. ix and fx = (nget nodes (o + 3 - sx) -. ox) *. ix in
  let ny = (nget nodes (o + 1 + sy) -. oy) *. iy and fy = (nget nodes (o + 4 - sy) -. oy) *. iy in
  let nz = (nget nodes (o + 2 + sz) -. oz) *. iz and fz = (nget nodes (o + 5 - sz) -. oz) *. iz in
  let lo = fmax (fmax nx ny) (fmax nz t0) in
  let hi = fmin (fmin fx fy) (fmin fz t1) in
  if lo <= hi then lo else infinity

(* Never inlined (nor [iter_s]): a caller passing a constant [tmin] would
   have it unboxed by the inliner and boxed again at every leaf call.
   Children are tested when their parent is reached: the nearer one hit is
   visited next, the farther one pushed with its entry distance, and popped
   only if still in front of the nearest hit found meanwhile. *)
let[@inline never] nearest_st st b (r : Ray.scratch) tmin (h : Hit.t) c1 c2 f =
  let nodes = b.nodes in
  let ident = Array.length b.prims = 0 in
  if Bigarray.Array1.dim nodes = 0 then false
  else begin
    let ox = r.ox and oy = r.oy and oz = r.oz in
    let ix = inv r.dx and iy = inv r.dy and iz = inv r.dz in
    let sx = if ix < 0. then 3 else 0 and sy = if iy < 0. then 3 else 0 and sz = if iz < 0. then 3 else 0 in
    if box_entry nodes 0 sx sy sz ox oy oz ix iy iz tmin h.t = infinity then false
    else begin
      let base = reserve st b.depth in
      let stack = st.slots and dist = st.dist in
      let sp = ref base and k = ref 0 and go = ref true and found = ref false in
      while !go do
        let kk = !k in
        let c = int_of_float (nget nodes ((8 * kk) + 7)) in
        let pop =
          if c > 0 then begin
            let first = int_of_float (nget nodes ((8 * kk) + 6)) in
            for j = first to first + c - 1 do
              if f c1 c2 r tmin h (if ident then j else Array.unsafe_get b.prims j) then found := true
            done;
            true
          end
          else begin
            let left = kk + 1 and right = int_of_float (nget nodes ((8 * kk) + 6)) in
            let tl = box_entry nodes left sx sy sz ox oy oz ix iy iz tmin h.t
            and tr = box_entry nodes right sx sy sz ox oy oz ix iy iz tmin h.t in
            if tl < infinity then begin
              if tr < infinity then begin
                if tl <= tr then (
                  Array.unsafe_set stack !sp right;
                  Float.Array.unsafe_set dist !sp tr;
                  k := left)
                else (
                  Array.unsafe_set stack !sp left;
                  Float.Array.unsafe_set dist !sp tl;
                  k := right);
                incr sp
              end
              else k := left;
              false
            end
            else if tr < infinity then (
              k := right;
              false)
            else true
          end
        in
        if pop then begin
          let searching = ref true in
          while !searching do
            if !sp = base then (
              searching := false;
              go := false)
            else begin
              decr sp;
              if Float.Array.unsafe_get dist !sp <= h.t then (
                k := Array.unsafe_get stack !sp;
                searching := false)
            end
          done
        end
      done;
      st.top <- base;
      !found
    end
  end

let[@inline never] iter_st st b (r : Ray.scratch) tmin c1 c2 f =
  let nodes = b.nodes and tmax = r.far in
  let ident = Array.length b.prims = 0 in
  if Bigarray.Array1.dim nodes = 0 then true
  else begin
    let ox = r.ox and oy = r.oy and oz = r.oz in
    let ix = inv r.dx and iy = inv r.dy and iz = inv r.dz in
    let sx = if ix < 0. then 3 else 0 and sy = if iy < 0. then 3 else 0 and sz = if iz < 0. then 3 else 0 in
    let base = reserve st b.depth in
    let stack = st.slots in
    let sp = ref base and k = ref 0 and go = ref true and ok = ref true in
    (* children are tested at their parent, the left one visited first
       (the order crossings are reported in is the same as testing each
       node when it is reached), and only the ones hit are pushed *)
    if not (box_hit nodes 0 sx sy sz ox oy oz ix iy iz tmin tmax) then go := false;
    while !go do
      let kk = !k in
      let c = int_of_float (nget nodes ((8 * kk) + 7)) in
      let pop =
        if c > 0 then begin
          let first = int_of_float (nget nodes ((8 * kk) + 6)) in
          let j = ref first in
          while !j < first + c && f c1 c2 r tmin (if ident then !j else Array.unsafe_get b.prims !j) do
            incr j
          done;
          if !j < first + c then (ok := false; go := false; false) else true
        end
        else begin
          let left = kk + 1 and right = int_of_float (nget nodes ((8 * kk) + 6)) in
          let hl = box_hit nodes left sx sy sz ox oy oz ix iy iz tmin tmax
          and hr = box_hit nodes right sx sy sz ox oy oz ix iy iz tmin tmax in
          if hl then begin
            if hr then (Array.unsafe_set stack !sp right; incr sp);
            k := left;
            false
          end
          else if hr then (k := right; false)
          else true
        end
      in
      if pop then if !sp = base then go := false else (decr sp; k := Array.unsafe_get stack !sp)
    done;
    st.top <- base;
    !ok
  end

let stack () = Scratch.get stack_key
let nearest_s b r tmin h c1 c2 f = nearest_st (stack ()) b r tmin h c1 c2 f
let iter_s b r tmin c1 c2 f = iter_st (stack ()) b r tmin c1 c2 f

let nearest b r tmin h f =
  ignore (nearest_s b (Ray.of_ray r) tmin h f () (fun f () _ _ _ i -> f i; false))

let iter b r tmin tmax f =
  let s = Ray.of_ray r in
  s.far <- tmax;
  iter_s b s tmin f () (fun f () _ _ i -> f i)

let renumber (b : t) =
  (* a tree already renumbered calls back with positions: its order is
     the identity *)
  let order = if Array.length b.prims = b.n then Array.copy b.prims else Array.init b.n Fun.id in
  ({ b with prims = [||] }, order)

let bytes (b : t) = (4 * Bigarray.Array1.dim b.nodes) + (8 * Array.length b.prims)
