(* The binned SAH build (see sah.mli). *)

(* Node k is 8 single-precision floats at nodes.(8k .. 8k+7), 32 bytes
   (two nodes to a cache line): its box (min x, y, z, max x, y, z), then
   two integers stored as floats: for a leaf, the first entry in [prims]
   and the primitive count (> 0); for an interior node, the index of its
   second child (the first is k+1) and -(axis+1) for the axis it was
   split along. *)
type f32 = (float, Bigarray.float32_elt, Bigarray.c_layout) Bigarray.Array1.t
type tree = { nodes : f32; prims : int array; depth : int }

(* Node indices and primitive offsets are stored in float32: exact below
   2^24. *)
let max_prims = 1 lsl 23
let fget = Float.Array.unsafe_get
let fset = Float.Array.unsafe_set

(* fmin/max call C (signbit) to order NaN and -0; boxes hold neither *)
let[@inline] fmin (a : float) b = if a < b then a else b
let[@inline] fmax (a : float) b = if a > b then a else b
let bins = 16

(* fewer primitives are built on one domain *)
let parallel_min = 1 lsl 14

let half_area x0 y0 z0 x1 y1 z1 =
  let dx = x1 -. x0 and dy = y1 -. y0 and dz = z1 -. z0 in
  (dx *. dy) +. (dy *. dz) +. (dz *. dx)

(* float32 copies of box bounds, rounded outward: a box only grows *)
let down x = if Float.is_finite x then x -. (Float.abs x *. 0x1p-22) -. 1e-37 else x
let up x = if Float.is_finite x then x +. (Float.abs x *. 0x1p-22) +. 1e-37 else x

(* What a build reads: the primitives' boxes and costs, and the
   permutation it sorts in place (each subtree owns a range of it). Boxes
   and costs are copies kept in the permutation's order, swapped with it:
   a node reads its primitives' data in sequence, not scattered over the
   arrays (at 10^6 boxes, what the build spent its time waiting for);
   centroids are taken from the boxes where needed. *)
type input = {
  leaf_size : int;
  node_cost : float;
  cost : Float.Array.t;
  boxes : Float.Array.t;
  uniform : bool;  (** every cost is 1: [cost] need not follow the permutation *)
  prims : int array;
}

(* a primitive's centroid, from its box (as the build always took it) *)
let[@inline] centre boxes i a = 0.5 *. (fget boxes ((6 * i) + a) +. fget boxes ((6 * i) + 3 + a))

let[@inline] swap_floats a k i j =
  for x = 0 to k - 1 do
    let t = fget a ((k * i) + x) in
    fset a ((k * i) + x) (fget a ((k * j) + x));
    fset a ((k * j) + x) t
  done

(* exchange the primitives at positions [i] and [j], with their data *)
let swap inp i j =
  let p = inp.prims in
  let t = p.(i) in
  p.(i) <- p.(j);
  p.(j) <- t;
  swap_floats inp.boxes 6 i j;
  if not inp.uniform then swap_floats inp.cost 1 i j

(* One builder per task: bin scratch, and the nodes it has written,
   numbered depth first from 0. A range of at most [defer] primitives is
   not built but left as a placeholder node (slot 7 = 0, slot 6 = its
   index in [pending]) for a task of its own. *)
type builder = {
  mutable buf : Float.Array.t;
  mutable count : int;
  mutable max_depth : int;
  defer : int;
  mutable pending : (int * int * int) list;  (** lo, hi, depth; last deferred first *)
  mutable npending : int;
  bbox : Float.Array.t;
  bcent : Float.Array.t;  (** per bin: its centroids' bounds *)
  mutable known : Float.Array.t;
      (** per depth, for the left and the right child of a node split by
          bins: box, centroid bounds and total cost, 13 floats each *)
  bcount : int array;
  bcost : Float.Array.t;
  rcost : Float.Array.t;
  rarea : Float.Array.t;
  rcount : int array;
}

let builder ~defer cap =
  {
    buf = Float.Array.create (8 * max 1 cap);
    count = 0;
    max_depth = 1;
    defer;
    pending = [];
    npending = 0;
    bbox = Float.Array.create (6 * bins);
    bcent = Float.Array.create (6 * bins);
    known = Float.Array.create (26 * 64);
    bcount = Array.make bins 0;
    bcost = Float.Array.create bins;
    rcost = Float.Array.create bins;
    rarea = Float.Array.create bins;
    rcount = Array.make bins 0;
  }

let placeholder = 0.

(* the node [k] is about to be written *)
let reserve_node bld =
  let k = bld.count in
  if 8 * (k + 1) > Float.Array.length bld.buf then begin
    let a = Float.Array.create (2 * Float.Array.length bld.buf) in
    Float.Array.blit bld.buf 0 a 0 (8 * k);
    bld.buf <- a
  end;
  bld.count <- k + 1;
  k

(* [side]: 0 or 1 when the node is the left or right child of a split by
   bins, whose bins gave its bounds (stored in [known] at [depth]); -1
   when they are to be computed *)
let rec node inp bld lo hi depth side =
  if hi - lo <= bld.defer then begin
    let k = reserve_node bld in
    fset bld.buf ((8 * k) + 6) (float bld.npending);
    fset bld.buf ((8 * k) + 7) placeholder;
    bld.pending <- (lo, hi, depth) :: bld.pending;
    bld.npending <- bld.npending + 1;
    k
  end
  else begin
    let { leaf_size; node_cost; cost; boxes; _ } = inp in
    let { bbox; bcount; bcost; rcost; rarea; rcount; _ } = bld in
    let k = reserve_node bld in
    let nodes = bld.buf in
    if depth > bld.max_depth then bld.max_depth <- depth;
    let bx0 = ref infinity and by0 = ref infinity and bz0 = ref infinity in
    let bx1 = ref neg_infinity and by1 = ref neg_infinity and bz1 = ref neg_infinity in
    let cx0 = ref infinity and cy0 = ref infinity and cz0 = ref infinity in
    let cx1 = ref neg_infinity and cy1 = ref neg_infinity and cz1 = ref neg_infinity in
    let total = ref 0. in
    if side >= 0 then begin
      let q = 13 * ((2 * depth) + side) and kn = bld.known in
      bx0 := fget kn q;
      by0 := fget kn (q + 1);
      bz0 := fget kn (q + 2);
      bx1 := fget kn (q + 3);
      by1 := fget kn (q + 4);
      bz1 := fget kn (q + 5);
      cx0 := fget kn (q + 6);
      cy0 := fget kn (q + 7);
      cz0 := fget kn (q + 8);
      cx1 := fget kn (q + 9);
      cy1 := fget kn (q + 10);
      cz1 := fget kn (q + 11);
      total := fget kn (q + 12)
    end
    else
      for i = lo to hi - 1 do
        total := !total +. fget cost i;
        let o = 6 * i in
        bx0 := fmin !bx0 (fget boxes o);
        by0 := fmin !by0 (fget boxes (o + 1));
        bz0 := fmin !bz0 (fget boxes (o + 2));
        bx1 := fmax !bx1 (fget boxes (o + 3));
        by1 := fmax !by1 (fget boxes (o + 4));
        bz1 := fmax !bz1 (fget boxes (o + 5));
        let x = centre boxes i 0 and y = centre boxes i 1 and z = centre boxes i 2 in
        cx0 := fmin !cx0 x;
        cy0 := fmin !cy0 y;
        cz0 := fmin !cz0 z;
        cx1 := fmax !cx1 x;
        cy1 := fmax !cy1 y;
        cz1 := fmax !cz1 z
      done;
    let o = 8 * k in
    fset nodes o !bx0;
    fset nodes (o + 1) !by0;
    fset nodes (o + 2) !bz0;
    fset nodes (o + 3) !bx1;
    fset nodes (o + 4) !by1;
    fset nodes (o + 5) !bz1;
    let m = hi - lo in
    let leaf () =
      fset nodes ((8 * k) + 6) (float lo);
      fset nodes ((8 * k) + 7) (float m)
    in
    let ex = !cx1 -. !cx0 and ey = !cy1 -. !cy0 and ez = !cz1 -. !cz0 in
    let axis = if ex >= ey && ex >= ez then 0 else if ey >= ez then 1 else 2 in
    let c0 = match axis with 0 -> !cx0 | 1 -> !cy0 | _ -> !cz0 in
    let ext = match axis with 0 -> ex | 1 -> ey | _ -> ez in
    (if m <= 1 then leaf ()
    else if not (ext > 0.) then
      if m <= leaf_size then leaf ()
      else split inp bld k lo hi (lo + (m / 2)) axis depth false
    else begin
      (* bin the centroids along the widest axis, then sweep for the SAH *)
      Array.fill bcount 0 bins 0;
      Float.Array.fill bcost 0 bins 0.;
      let bcent = bld.bcent in
      for b = 0 to bins - 1 do
        for a = 0 to 2 do
          fset bbox ((6 * b) + a) infinity;
          fset bbox ((6 * b) + 3 + a) neg_infinity;
          fset bcent ((6 * b) + a) infinity;
          fset bcent ((6 * b) + 3 + a) neg_infinity
        done
      done;
      let scale = float bins /. ext *. (1. -. 1e-9) in
      let bin_of i = Int.min (bins - 1) (int_of_float ((centre boxes i axis -. c0) *. scale)) in
      for i = lo to hi - 1 do
        let b = bin_of i in
        bcount.(b) <- bcount.(b) + 1;
        fset bcost b (fget bcost b +. fget cost i);
        for a = 0 to 2 do
          let q = (6 * b) + a in
          fset bbox q (fmin (fget bbox q) (fget boxes ((6 * i) + a)));
          fset bbox (q + 3) (fmax (fget bbox (q + 3)) (fget boxes ((6 * i) + 3 + a)));
          let c = centre boxes i a in
          fset bcent q (fmin (fget bcent q) c);
          fset bcent (q + 3) (fmax (fget bcent (q + 3)) c)
        done
      done;
      (* right-to-left sweep *)
      let x0 = ref infinity and y0 = ref infinity and z0 = ref infinity in
      let x1 = ref neg_infinity and y1 = ref neg_infinity and z1 = ref neg_infinity in
      let acc = ref 0 and acost = ref 0. in
      for b = bins - 1 downto 1 do
        let q = 6 * b in
        x0 := fmin !x0 (fget bbox q);
        y0 := fmin !y0 (fget bbox (q + 1));
        z0 := fmin !z0 (fget bbox (q + 2));
        x1 := fmax !x1 (fget bbox (q + 3));
        y1 := fmax !y1 (fget bbox (q + 4));
        z1 := fmax !z1 (fget bbox (q + 5));
        acc := !acc + bcount.(b);
        acost := !acost +. fget bcost b;
        rcount.(b) <- !acc;
        fset rcost b !acost;
        fset rarea b (if !acc = 0 then 0. else half_area !x0 !y0 !z0 !x1 !y1 !z1)
      done;
      x0 := infinity; y0 := infinity; z0 := infinity;
      x1 := neg_infinity; y1 := neg_infinity; z1 := neg_infinity;
      let lc = ref 0 and lcost = ref 0. and best = ref infinity and best_b = ref 0 in
      for b = 0 to bins - 2 do
        let q = 6 * b in
        x0 := fmin !x0 (fget bbox q);
        y0 := fmin !y0 (fget bbox (q + 1));
        z0 := fmin !z0 (fget bbox (q + 2));
        x1 := fmax !x1 (fget bbox (q + 3));
        y1 := fmax !y1 (fget bbox (q + 4));
        z1 := fmax !z1 (fget bbox (q + 5));
        lc := !lc + bcount.(b);
        lcost := !lcost +. fget bcost b;
        if !lc > 0 && rcount.(b + 1) > 0 then begin
          let cost =
            (!lcost *. half_area !x0 !y0 !z0 !x1 !y1 !z1)
            +. (fget rcost (b + 1) *. fget rarea (b + 1))
          in
          if cost < !best then (best := cost; best_b := b)
        end
      done;
      let leaf_cost = !total *. half_area !bx0 !by0 !bz0 !bx1 !by1 !bz1 in
      (* a node's walk costs [node_cost] primitive tests of cost 1 *)
      let split_cost = !best +. (node_cost *. half_area !bx0 !by0 !bz0 !bx1 !by1 !bz1) in
      if m <= leaf_size && split_cost >= leaf_cost then leaf ()
      else if !best = infinity then split inp bld k lo hi (lo + (m / 2)) axis depth false
      else begin
        (* partition positions lo..hi-1 (primitives and their data) by
           bin <= best_b *)
        let i = ref lo and j = ref (hi - 1) in
        while !i <= !j do
          if bin_of !i <= !best_b then incr i
          else begin
            swap inp !i !j;
            decr j
          end
        done;
        if !i = lo || !i = hi then split inp bld k lo hi (lo + (m / 2)) axis depth false
        else begin
          (* the children's bounds and costs are their bins' *)
          let d = depth + 1 in
          if 26 * (d + 1) > Float.Array.length bld.known then begin
            let a = Float.Array.create (2 * 26 * (d + 1)) in
            Float.Array.blit bld.known 0 a 0 (Float.Array.length bld.known);
            bld.known <- a
          end;
          let kn = bld.known in
          for side = 0 to 1 do
            let q = 13 * ((2 * d) + side) in
            let b0 = if side = 0 then 0 else !best_b + 1 and b1 = if side = 0 then !best_b else bins - 1 in
            for a = 0 to 2 do
              let lo_ = ref infinity and hi_ = ref neg_infinity and clo = ref infinity and chi = ref neg_infinity in
              for b = b0 to b1 do
                let r = (6 * b) + a in
                lo_ := fmin !lo_ (fget bbox r);
                hi_ := fmax !hi_ (fget bbox (r + 3));
                clo := fmin !clo (fget bcent r);
                chi := fmax !chi (fget bcent (r + 3))
              done;
              fset kn (q + a) !lo_;
              fset kn (q + 3 + a) !hi_;
              fset kn (q + 6 + a) !clo;
              fset kn (q + 9 + a) !chi
            done;
            let c = ref 0. in
            for b = b0 to b1 do
              c := !c +. fget bcost b
            done;
            fset kn (q + 12) !c
          done;
          split inp bld k lo hi !i axis depth true
        end
      end
    end);
    k
  end

and split inp bld k lo hi mid axis depth by_bins =
  ignore (node inp bld lo mid (depth + 1) (if by_bins then 0 else -1));
  let r = node inp bld mid hi (depth + 1) (if by_bins then 1 else -1) in
  (* the nodes may have moved to a larger array *)
  fset bld.buf ((8 * k) + 6) (float r);
  fset bld.buf ((8 * k) + 7) (float (-(axis + 1)))

(* [par n f] runs [f 0] ... [f (n-1)], in any order or at once. *)
let build ?(leaf_size = 4) ?(node_cost = 1.) ?cost ?par boxes =
  let n = Float.Array.length boxes / 6 in
  let uniform = cost = None in
  let cost = match cost with Some c -> Float.Array.copy c | None -> Float.Array.make n 1. in
  let boxes = Float.Array.copy boxes in
  if n > max_prims then invalid_arg "Bvh.build: more than 2^23 primitives";
  let prims = Array.init n Fun.id in
  let inp = { leaf_size; node_cost; cost; boxes; uniform; prims } in
  (* In parallel, the top of the tree is built first, leaving ranges of
     at most n/16 primitives (at least 16 tasks) to tasks of their own;
     the tasks' nodes are then spliced in where their placeholders are.
     The tree is the same node for node: a subtree depends only on its
     own range of the permutation. *)
  let defer = match par with Some _ when n >= parallel_min -> n / 16 | _ -> 0 in
  let top = builder ~defer (if defer = 0 then 2 * n else 64) in
  if n > 0 then ignore (node inp top 0 n 1 (-1));
  let tasks = Array.of_list (List.rev top.pending) in
  let subs = Array.make (Array.length tasks) top in
  (match par with
  | Some par when Array.length tasks > 0 ->
      par (Array.length tasks) (fun t ->
          let lo, hi, depth = tasks.(t) in
          let b = builder ~defer:0 (2 * (hi - lo)) in
          ignore (node inp b lo hi depth (-1));
          subs.(t) <- b)
  | _ -> ());
  (* final position of each top node: a placeholder stands for its task's
     nodes *)
  let size k =
    let g = fget top.buf ((8 * k) + 7) in
    if g = placeholder then subs.(int_of_float (fget top.buf ((8 * k) + 6))).count else 1
  in
  let at = Array.make (top.count + 1) 0 in
  for k = 0 to top.count - 1 do
    at.(k + 1) <- at.(k) + size k
  done;
  let c = at.(top.count) in
  let out = Bigarray.Array1.create Bigarray.float32 Bigarray.c_layout (8 * c) in
  let emit src j dst ~child =
    for a = 0 to 2 do
      out.{(8 * dst) + a} <- down (fget src ((8 * j) + a));
      out.{(8 * dst) + 3 + a} <- up (fget src ((8 * j) + 3 + a))
    done;
    let g = fget src ((8 * j) + 7) in
    let l = fget src ((8 * j) + 6) in
    out.{(8 * dst) + 6} <- (if g < 0. then float (child (int_of_float l)) else l);
    out.{(8 * dst) + 7} <- g
  in
  let max_depth = ref top.max_depth in
  for k = 0 to top.count - 1 do
    if fget top.buf ((8 * k) + 7) = placeholder then begin
      let b = subs.(int_of_float (fget top.buf ((8 * k) + 6))) in
      if b.max_depth > !max_depth then max_depth := b.max_depth;
      let base = at.(k) in
      for j = 0 to b.count - 1 do
        emit b.buf j (base + j) ~child:(fun r -> base + r)
      done
    end
    else emit top.buf k at.(k) ~child:(fun r -> at.(r))
  done;
  { nodes = out; prims; depth = !max_depth + 1 }
