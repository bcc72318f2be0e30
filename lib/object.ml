type t = {
  geom : geom;
  xform : Transform.t;
  texture : Texture.t;
  back : Texture.t;
  interior : Interior.t;
  no_shadow : bool;
  inverted : bool;
  clip : t array;
  bound : t array;
  bounds : (Vec3.t * Vec3.t) option;
  index : index option;
  inv : Float.Array.t;
  uv : bool;
  lights : int;
  photon : Photon.flags;
}

and geom = Prim of Shape.t | Union of t array | Intersection of t array | Merge of t array

and index = { bvh : Bvh.t; bounded : t array; unbounded : t array }

let box_union a b =
  match (a, b) with
  | Some (l1, h1), Some (l2, h2) -> Some (Vec3.min l1 l2, Vec3.max h1 h2)
  | _ -> None

(* [None] is the whole space here. *)
let box_inter a b =
  match (a, b) with
  | Some (l1, h1), Some (l2, h2) -> Some (Vec3.max l1 l2, Vec3.min h1 h2)
  | Some x, None | None, Some x -> Some x
  | None, None -> None

let world_box xf = function
  | None -> None
  | Some ((lo : Vec3.t), (hi : Vec3.t)) ->
      if Transform.is_identity xf then Some (lo, hi)
      else
        let c i =
          Transform.point xf
            (Vec3.make (if i land 1 = 0 then lo.x else hi.x) (if i land 2 = 0 then lo.y else hi.y)
               (if i land 4 = 0 then lo.z else hi.z))
        in
        let l = ref (c 0) and h = ref (c 0) in
        for i = 1 to 7 do
          l := Vec3.min !l (c i);
          h := Vec3.max !h (c i)
        done;
        Some (!l, !h)

(* The plane [n . p < d] (its inside; the other side when [inverted])
   moved by [xf], as [(n', c)] with the inside [n' . p < c]. *)
let moved_plane xf (n : Vec3.t) d inverted =
  let nw = Transform.normal xf n in
  let c = Vec3.dot nw (Transform.point xf (Vec3.scale (d /. Vec3.length2 n) n)) in
  if inverted then (Vec3.neg nw, -.c) else (nw, c)

(* A box ([None]: the whole space) as its low and high ends per axis,
   to cut one axis at a time, and back *)
let box_arrays = function
  | Some ((l : Vec3.t), (h : Vec3.t)) -> ([| l.x; l.y; l.z |], [| h.x; h.y; h.z |])
  | None -> ([| neg_infinity; neg_infinity; neg_infinity |], [| infinity; infinity; infinity |])

let box_of_arrays lo hi = Some (Vec3.make lo.(0) lo.(1) lo.(2), Vec3.make hi.(0) hi.(1) hi.(2))

(* The box [b] ([None]: the whole space) cut by the inside of the plane
   [n . p < c]: on each axis the normal has a part along, the plane
   bounds that coordinate given the box's range on the others (interval
   arithmetic). POV-Ray bounds a CSG intersection by its axis-aligned
   planes (a difference that cuts an object in half keeps the box of the
   half kept); this does the same, and trims by oblique planes too. Each
   bound is moved out by 1e-9 of the magnitudes summed, so that rounding
   never cuts the surface lying on it. *)
let cut_by_plane (n : Vec3.t) c b =
  let lo, hi = box_arrays b in
  for k = 0 to 2 do
    let nk = Vec3.get n k in
    if nk <> 0. then begin
      (* n_k p_k < c - sum_{j <> k} n_j p_j, whose largest value over the
         box is [rest] *)
      let rest = ref c and size = ref (Float.abs c) in
      for j = 0 to 2 do
        let nj = Vec3.get n j in
        if j <> k && nj <> 0. then begin
          rest := !rest +. Float.max (-.nj *. lo.(j)) (-.nj *. hi.(j));
          size := !size +. Float.abs (nj *. lo.(j)) +. Float.abs (nj *. hi.(j))
        end
      done;
      let v = !rest /. nk in
      if Float.is_finite v then begin
        let pad = 1e-9 *. ((!size /. Float.abs nk) +. Float.abs v) in
        if nk > 0. then hi.(k) <- Float.min hi.(k) (v +. pad) else lo.(k) <- Float.max lo.(k) (v -. pad)
      end
    end
  done;
  if Array.for_all (fun x -> x = neg_infinity) lo && Array.for_all (fun x -> x = infinity) hi then b
  else box_of_arrays lo hi

(* [o]'s inside as a plane's half-space in the frame [xf] takes the
   world into, if it is one *)
let half_space xf o =
  match o.geom with
  | Prim (Shape.Plane { normal; offset }) when Array.length o.clip = 0 ->
      Some (moved_plane (Transform.then_ o.xform xf) normal offset o.inverted)
  | _ -> None

(* The box [b] cut by the inside of a quadric without mixed terms
   ([Algebraic.quadric]) moved by [xf], when [xf] keeps the axes (scales
   and translations): POV-Ray bounds a quadric in a CSG intersection by
   the box the other parts leave, and so does this. With the squares
   completed, the inside is [sum_k a_k (x_k - c_k)^2 + g < 0] (a term
   [d_k x_k] where [a_k = 0]); on an axis with [a_k > 0] it lies within
   [c_k -+ sqrt (r / a_k)], [r] the largest value of [-g] less the other
   terms over the box (interval arithmetic), twice over the axes. *)
let cut_by_quadric xf (q : float array) inverted b =
  let vx = Transform.vector xf Vec3.unit_x and vy = Transform.vector xf Vec3.unit_y
  and vz = Transform.vector xf Vec3.unit_z and t = Transform.point xf Vec3.zero in
  (* off the diagonal, what a rotation and its inverse leave by
     rounding (1e-16 of the scale) counts as zero: far inside the bounds'
     1e-9 margins *)
  let off u v = Float.abs u <= 1e-12 *. Float.abs v in
  if not (off vx.y vx.x && off vx.z vx.x && off vy.x vy.y && off vy.z vy.y && off vz.x vz.z && off vz.y vz.z) then b
  else begin
    let sc = [| vx.x; vy.y; vz.z |] and tr = [| t.x; t.y; t.z |] in
    let q = if inverted then Array.map Float.neg q else q in
    let wlo, whi = box_arrays b in
    (* the box in the quadric's own space *)
    let ends k = ((wlo.(k) -. tr.(k)) /. sc.(k), (whi.(k) -. tr.(k)) /. sc.(k)) in
    let l = Array.init 3 (fun k -> let u, v = ends k in Float.min u v)
    and h = Array.init 3 (fun k -> let u, v = ends k in Float.max u v) in
    let a = [| q.(0); q.(1); q.(2) |] and d = [| q.(3); q.(4); q.(5) |] in
    let c = Array.init 3 (fun k -> if a.(k) <> 0. then -.d.(k) /. (2. *. a.(k)) else 0.) in
    let g = ref q.(6) in
    for k = 0 to 2 do
      if a.(k) <> 0. then g := !g -. (d.(k) *. d.(k) /. (4. *. a.(k)))
    done;
    (* the largest value of minus axis j's term over the box *)
    let neg_max j =
      if a.(j) > 0. then
        let m = if c.(j) < l.(j) then l.(j) -. c.(j) else if c.(j) > h.(j) then c.(j) -. h.(j) else 0. in
        -.a.(j) *. m *. m
      else if a.(j) < 0. then
        let m = Float.max (Float.abs (l.(j) -. c.(j))) (Float.abs (h.(j) -. c.(j))) in
        -.a.(j) *. m *. m
      else if d.(j) = 0. then 0.
      else Float.max (-.d.(j) *. l.(j)) (-.d.(j) *. h.(j))
    in
    let cut = Array.make 3 false in
    for _ = 1 to 2 do
      for k = 0 to 2 do
        let r = ref (-. !g) in
        for j = 0 to 2 do
          if j <> k then r := !r +. neg_max j
        done;
        let r = !r in
        let pad x = 1e-9 *. (Float.abs x +. Float.abs c.(k) +. Float.abs r) in
        if Float.is_finite r && r >= 0. then
          if a.(k) > 0. then begin
            let w = Float.sqrt (r /. a.(k)) in
            let lo = c.(k) -. w and hi = c.(k) +. w in
            let lo = lo -. pad lo and hi = hi +. pad hi in
            if lo > l.(k) then (l.(k) <- lo; cut.(k) <- true);
            if hi < h.(k) then (h.(k) <- hi; cut.(k) <- true)
          end
          else if a.(k) = 0. && d.(k) <> 0. then begin
            let v = r /. d.(k) in
            if d.(k) > 0. then (let v = v +. pad v in if v < h.(k) then (h.(k) <- v; cut.(k) <- true))
            else (let v = v -. pad v in if v > l.(k) then (l.(k) <- v; cut.(k) <- true))
          end
      done
    done;
    if not (cut.(0) || cut.(1) || cut.(2)) then b
    else begin
      (* back to the world, on the axes cut *)
      for k = 0 to 2 do
        if cut.(k) then begin
          let u = (sc.(k) *. l.(k)) +. tr.(k) and v = (sc.(k) *. h.(k)) +. tr.(k) in
          let u, v = (Float.min u v, Float.max u v) in
          let p = 1e-9 *. (Float.abs u +. Float.abs v +. Float.abs tr.(k)) in
          wlo.(k) <- Float.max wlo.(k) (u -. p);
          whi.(k) <- Float.min whi.(k) (v +. p)
        end
      done;
      box_of_arrays wlo whi
    end
  end

(* [o]'s inside as a quadric without mixed terms, if it is one, with its
   transform into [xf]'s frame *)
let quadric_part xf o =
  match o.geom with
  | Prim (Shape.Algebraic s) when Array.length o.clip = 0 ->
      Option.map (fun q -> (Transform.then_ o.xform xf, q, o.inverted)) (Algebraic.quadric s)
  | _ -> None

(* The box of where the insides of all of [parts] meet, within [b]:
   [box part] for all but planes and quadrics, then cut by the planes
   (the more the box is bounded, the more an oblique plane cuts), then by
   the quadrics. *)
let meet box xf b parts =
  let solids, cutters =
    List.partition_map
      (fun o ->
        match half_space xf o with
        | Some p -> Right (Either.Left p)
        | None -> ( match quadric_part xf o with Some q -> Right (Either.Right q) | None -> Left o))
      (Array.to_list parts)
  in
  let planes, quadrics = List.partition_map Fun.id cutters in
  let b = List.fold_left (fun b o -> box_inter b (box o)) b solids in
  let b = List.fold_left (fun b (n, c) -> cut_by_plane n c b) b planes in
  if quadrics = [] then b
  else
    (* and by the planes again: a plane's normal off an axis by rounding
       (a rotation undone in the frame) cuts only once the quadrics have
       bounded the other axes *)
    let b = List.fold_left (fun b (x, q, inv) -> cut_by_quadric x q inv b) b quadrics in
    List.fold_left (fun b (n, c) -> cut_by_plane n c b) b planes

(* Bounds of where [inside] can be true (a disc's inside is a half-space,
   wider than its surface): what intersections and clips may trust. *)
let rec solid_box o =
  match o.geom with
  | Prim (Shape.Disc _ | Shape.Height_field _) -> None  (* a height field: the column under it too *)
  | Prim (Shape.Plane _) -> clip_box o.clip (meet solid_box Transform.identity None [| { o with clip = [||] } |])
  | Prim _ | Intersection _ -> o.bounds
  | Union cs | Merge cs ->
      if Array.length cs = 0 then o.bounds
      else Array.fold_left (fun b c -> box_union b (solid_box c)) (solid_box cs.(0)) cs

and clip_box clip b = meet solid_box Transform.identity b clip

(* [solid_box] in a frame: [finv] takes the world into it. A CSG's parts
   carry their transforms to the world; in the frame the CSG was written
   in, its cutting planes are the ones written (axis-aligned, say) even
   when the whole was then rotated, and the box found there, carried to
   the world, is the one POV-Ray gets by transforming the CSG's box. *)
let rec frame_box finv o =
  let own =
    match o.geom with
    | Prim (Shape.Disc _ | Shape.Height_field _) -> None
    | Prim (Shape.Plane _) -> meet (frame_box finv) finv None [| { o with clip = [||] } |]
    | Prim s -> if o.inverted then None else world_box (Transform.then_ o.xform finv) (Shape.bounds s)
    | Intersection cs -> meet (frame_box finv) finv None cs
    | Union cs | Merge cs ->
        if Array.length cs = 0 then None
        else Array.fold_left (fun b c -> box_union b (frame_box finv c)) (frame_box finv cs.(0)) cs
  in
  meet (frame_box finv) finv own o.clip

(* The scale factor of a similarity (rotation, uniform scale, translation),
   or [None]. *)
let similarity xf =
  let c0 = Transform.vector xf Vec3.unit_x and c1 = Transform.vector xf Vec3.unit_y
  and c2 = Transform.vector xf Vec3.unit_z in
  let l0 = Vec3.length2 c0 in
  let close a b = Float.abs (a -. b) <= 1e-12 *. l0 in
  if close (Vec3.length2 c1) l0 && close (Vec3.length2 c2) l0 && close (Vec3.dot c0 c1) 0.
     && close (Vec3.dot c1 c2) 0. && close (Vec3.dot c0 c2) 0. && l0 > 0.
  then Some (Float.sqrt l0)
  else None

(* A sphere moved by a similarity is a sphere: no transform to apply per
   ray (and the scene tests it from a flat array). *)
let fold xform shape =
  match shape with
  | Shape.Sphere { center; radius } when not (Transform.is_identity xform) -> (
      match similarity xform with
      | Some k -> (Transform.identity, Shape.sphere (Transform.point xform center) (k *. radius))
      | None -> (xform, shape))
  | _ -> (xform, shape)

(* The inverse of [xf] as a 3x4 row-major matrix, translation last (what
   a per-ray transform reads without allocating). *)
let inverse_matrix xf =
  let c0 = Transform.inv_vector xf Vec3.unit_x and c1 = Transform.inv_vector xf Vec3.unit_y
  and c2 = Transform.inv_vector xf Vec3.unit_z and t = Transform.inv_point xf Vec3.zero in
  Float.Array.of_list [ c0.x; c1.x; c2.x; c0.y; c1.y; c2.y; c0.z; c1.z; c2.z; t.x; t.y; t.z ]

let identity_matrix = inverse_matrix Transform.identity

let make ?(xform = Transform.identity) ?(texture = Texture.default) ?back ?(interior = Interior.default)
    ?(no_shadow = false) ?(inverted = false) ?(clip = [||]) ?(lights = 0) ?(photon = Photon.none) shape =
  let back = match back with Some b -> b | None -> texture in
  let uv = Texture.uses_uv texture || Texture.uses_uv back in
  (* a uv-mapped sphere keeps its transform: its uv is taken in its own frame *)
  let xform, shape = if uv then (xform, shape) else fold xform shape in
  let b = if inverted then None else world_box xform (Shape.bounds shape) in
  let inv = if Transform.is_identity xform then identity_matrix else inverse_matrix xform in
  { geom = Prim shape; xform; texture; back; interior; no_shadow; inverted; clip; bound = [||]; bounds = clip_box clip b;
    index = None; inv; uv; lights; photon }

let node geom clip b =
  {
    geom;
    xform = Transform.identity;
    texture = Texture.default;
    back = Texture.default;
    interior = Interior.default;
    (* a node casts no shadow when none of its leaves does: shadow rays
       pass it by without walking its crossings *)
    no_shadow =
      (match geom with
      | Union cs | Intersection cs | Merge cs -> Array.length cs > 0 && Array.for_all (fun c -> c.no_shadow) cs
      | Prim _ -> false);
    inverted = false;
    clip;
    bound = [||];
    bounds = clip_box clip b;
    index = None;
    inv = identity_matrix;
    uv = false;
    lights = 0;
    photon = Photon.none;
  }

(* A BVH over the children of a large union. *)
let index_min = 8

let make_index cs =
  let bounded, unbounded =
    List.partition (fun c -> match c.bounds with Some (lo, hi) -> Vec3.is_finite lo && Vec3.is_finite hi | None -> false)
      (Array.to_list cs)
  in
  let bounded = Array.of_list bounded in
  let boxes = Float.Array.create (6 * Array.length bounded) in
  Array.iteri
    (fun i c ->
      match c.bounds with
      | Some ((lo : Vec3.t), (hi : Vec3.t)) ->
          List.iteri (fun k x -> Float.Array.set boxes ((6 * i) + k) x)
            [ lo.x; lo.y; lo.z; Float.max lo.x hi.x; Float.max lo.y hi.y; Float.max lo.z hi.z ]
      | None -> ())
    bounded;
  let bvh, order = Bvh.renumber (Bvh.build boxes) in
  { bvh; bounded = Array.map (fun i -> bounded.(i)) order; unbounded = Array.of_list unbounded }

let union_box cs =
  if Array.length cs = 0 then Some (Vec3.zero, Vec3.zero)
  else Array.fold_left (fun b c -> box_union b c.bounds) cs.(0).bounds cs

let union ?(clip = [||]) cs =
  let n = node (Union cs) clip (union_box cs) in
  if Array.length cs >= index_min then { n with index = Some (make_index cs) } else n
let merge ?(clip = [||]) cs = node (Merge cs) clip (union_box cs)

(* [world], the box found in the world, trimmed by the box [in_frame]
   finds in the frame [frame] takes to the world, when that one is
   finite *)
let framed world frame in_frame =
  match frame with
  | Some f when not (Transform.is_identity f) -> (
      let finv = Transform.inverse f in
      match in_frame finv with
      | Some ((lo, hi) as b) when Vec3.is_finite lo && Vec3.is_finite hi -> box_inter world (world_box f (Some b))
      | _ -> world)
  | _ -> world

let intersection ?(clip = [||]) ?frame cs =
  let world = meet solid_box Transform.identity None cs in
  node (Intersection cs) clip (framed world frame (fun finv -> meet (frame_box finv) finv None cs))

let with_clip ?frame o clip =
  let clipped = { o with clip = Array.append o.clip clip } in
  (* what is kept lies in the object and the clip at once: a quadric or
     an intersection's parts met with the clip's planes together, so that
     a cone between planes is bounded by them (its own box, then the
     clip's, leaves it unbounded) *)
  let parts =
    match o.geom with
    | Intersection cs -> Some (Array.concat [ cs; o.clip; clip ])
    | Prim (Shape.Algebraic _) -> Some (Array.append [| { o with clip = [||] } |] clipped.clip)
    | _ -> None
  in
  let world = clip_box clip o.bounds in
  let world = match parts with Some ps -> box_inter world (meet solid_box Transform.identity None ps) | None -> world in
  let in_frame finv =
    let whole = frame_box finv clipped in
    match parts with Some ps -> box_inter whole (meet (frame_box finv) finv None ps) | None -> whole
  in
  { clipped with bounds = framed world frame in_frame }

(* A ray-level test (see [in_bound]): the object's box stays its own,
   since its crossings need not lie inside the bound. *)
let with_bound o bound = { o with bound = Array.append o.bound bound }

let rec invert o =
  match o.geom with
  | Prim s ->
      let b = if o.inverted then world_box o.xform (Shape.bounds s) else None in
      { o with inverted = not o.inverted; bounds = clip_box o.clip b }
  | Union cs | Merge cs -> with_bound (intersection ~clip:o.clip (Array.map invert cs)) o.bound
  | Intersection cs -> with_bound (merge ~clip:o.clip (Array.map invert cs)) o.bound

type found = { mutable leaf : t; local : Ray.scratch; pt : Ray.scratch }

let found o = { leaf = o; local = Ray.scratch (); pt = Ray.scratch () }

(* per domain, by nesting depth (a bound may have a bound): the query
   space of a bound's test *)
let bound_scratch =
  let any = make (Shape.sphere Vec3.zero 1.) in
  Scratch.key (fun () -> Scratch.levels ~initial:1 (fun () -> (Hit.create infinity, found any)))

let next_tmin (r : Ray.t) t =
  let dl = Vec3.length r.dir in
  let step = 1e-9 *. (1. +. (Float.abs t *. dl)) /. dl in
  Float.max (t +. step) (Float.succ t)

(* [Float.succ] is a function of the standard library (its argument
   would be boxed); the primitive under it is called directly *)
external next_after : float -> float -> float = "caml_nextafter_float" "caml_nextafter" [@@unboxed] [@@noalloc]

let[@inline] next_tmin_s (r : Ray.scratch) t =
  let dl = Float.sqrt ((r.dx *. r.dx) +. (r.dy *. r.dy) +. (r.dz *. r.dz)) in
  let step = 1e-9 *. (1. +. (Float.abs t *. dl)) /. dl in
  Float.max (t +. step) (next_after t infinity)

(* [r]'s origin taken into the primitive's own space, into [l] *)
let[@inline] local_origin o (r : Ray.scratch) (l : Ray.scratch) =
  let m = o.inv in
  let g = Float.Array.unsafe_get in
  l.ox <- (g m 0 *. r.ox) +. (g m 1 *. r.oy) +. (g m 2 *. r.oz) +. g m 9;
  l.oy <- (g m 3 *. r.ox) +. (g m 4 *. r.oy) +. (g m 5 *. r.oz) +. g m 10;
  l.oz <- (g m 6 *. r.ox) +. (g m 7 *. r.oy) +. (g m 8 *. r.oz) +. g m 11

(* [inside_s o f]: the inside test at the point held in [f.pt]; uses
   [f.local] for the point in a leaf's own space. *)
let rec inside_s o f =
  let raw =
    match o.geom with
    | Prim s ->
        let p = f.pt in
        if Transform.is_identity o.xform then Shape.inside_s s p <> o.inverted
        else begin
          local_origin o p f.local;
          Shape.inside_s s f.local <> o.inverted
        end
    | Union cs | Merge cs -> any_inside cs f 0
    | Intersection cs -> all_inside cs f 0 (-1)
  in
  raw && all_inside o.clip f 0 (-1)

and any_inside cs f i = i < Array.length cs && (inside_s (Array.unsafe_get cs i) f || any_inside cs f (i + 1))

(* every child but [skip] *)
and all_inside cs f i skip =
  i >= Array.length cs || ((i = skip || inside_s (Array.unsafe_get cs i) f) && all_inside cs f (i + 1) skip)

and none_inside cs f i skip =
  i >= Array.length cs || ((i = skip || not (inside_s (Array.unsafe_get cs i) f)) && none_inside cs f (i + 1) skip)

let inside o (p : Vec3.t) =
  let f = found o in
  f.pt.ox <- p.x;
  f.pt.oy <- p.y;
  f.pt.oz <- p.z;
  inside_s o f

let inside_pattern o =
  let key = Scratch.key (fun () -> found o) in
  Pattern.inside (fun (p : Vec3.m) ->
      let f = Scratch.get key in
      f.pt.ox <- p.mx;
      f.pt.oy <- p.my;
      f.pt.oz <- p.mz;
      inside_s o f)

(* if-based: Float.min/max are calls with boxed arguments (and order NaN
   and -0, which the comparison below does not need: no slab distance is
   NaN, the zero directions being set apart) *)
let fmin = Floats.fmin
let fmax = Floats.fmax

(* Where the ray leaves the box whose slabs it meets at [ax]/[bx],
   [ay]/[by], [az]/[bz] (a zero component's slab is no bound) *)
let[@inline] slab_exit (r : Ray.scratch) ax bx ay by az bz =
  fmin
    (if r.dx = 0. then infinity +. 0. else fmax ax bx)
    (fmin (if r.dy = 0. then infinity +. 0. else fmax ay by) (if r.dz = 0. then infinity +. 0. else fmax az bz))

(* Whether the ray misses the object's box within (tmin, tmax); inlined,
   so that a [tmax] read from a hit record is not boxed to be passed. *)
let[@inline] box_missed o (r : Ray.scratch) tmin tmax =
  match o.bounds with
  | None -> false
  | Some ((lo : Vec3.t), (hi : Vec3.t)) ->
      let ax = (lo.x -. r.ox) /. r.dx and bx = (hi.x -. r.ox) /. r.dx in
      let ay = (lo.y -. r.oy) /. r.dy and by = (hi.y -. r.oy) /. r.dy in
      let az = (lo.z -. r.oz) /. r.dz and bz = (hi.z -. r.oz) /. r.dz in
      (r.dx = 0. && (r.ox < lo.x || r.ox > hi.x))
      || (r.dy = 0. && (r.oy < lo.y || r.oy > hi.y))
      || (r.dz = 0. && (r.oz < lo.z || r.oz > hi.z))
      ||
      (* [+. 0.] unboxes the bounds and the infinities: a branch choosing
         between a boxed and an unboxed float would box the result, and
         the slab distances with it *)
      let tmin = tmin +. 0. and tmax = tmax +. 0. in
      let t0 =
        fmax tmin
          (fmax
             (if r.dx = 0. then neg_infinity +. 0. else fmin ax bx)
             (fmax (if r.dy = 0. then neg_infinity +. 0. else fmin ay by)
                (if r.dz = 0. then neg_infinity +. 0. else fmin az bz)))
      and t1 = fmin tmax (slab_exit r ax bx ay by az bz) in
      t0 > t1

(* Kinds of acceptance for [first_accepted]. *)
let by_clip = 0 and by_intersection = 1 and by_merge = 2

(* The ray in the primitive's own space: [r] itself, or [f.local] *)
let[@inline] local o (r : Ray.scratch) (f : found) =
  if Transform.is_identity o.xform then r
  else begin
    let m = o.inv and l = f.local in
    let g = Float.Array.unsafe_get in
    local_origin o r l;
    l.dx <- (g m 0 *. r.dx) +. (g m 1 *. r.dy) +. (g m 2 *. r.dz);
    l.dy <- (g m 3 *. r.dx) +. (g m 4 *. r.dy) +. (g m 5 *. r.dz);
    l.dz <- (g m 6 *. r.dx) +. (g m 7 *. r.dy) +. (g m 8 *. r.dz);
    l
  end

(* Where the ray leaves the object's box (infinity without one), a
   little past it: no crossing kept lies beyond. *)
let[@inline] box_far o (r : Ray.scratch) =
  match o.bounds with
  | None -> infinity +. 0.  (* unboxed, as in [box_missed] *)
  | Some ((lo : Vec3.t), (hi : Vec3.t)) ->
      let t1 =
        slab_exit r ((lo.x -. r.ox) /. r.dx) ((hi.x -. r.ox) /. r.dx) ((lo.y -. r.oy) /. r.dy)
          ((hi.y -. r.oy) /. r.dy) ((lo.z -. r.oz) /. r.dz) ((hi.z -. r.oz) /. r.dz)
      in
      t1 +. (1e-9 *. (1. +. Float.abs t1))

(* The query bound [h.t] lowered to where the ray leaves [o]'s box, for
   an object whose kept crossings all lie in its box (a clipped object,
   an intersection); the bound before, to put back when nothing is kept *)
let[@inline] stop_at_box o r (h : Hit.t) =
  let t = h.t in
  let far = box_far o r in
  if far < t then h.t <- far;
  t

let rec hit_s o (r : Ray.scratch) tmin (h : Hit.t) f =
  if Array.length o.bound > 0 && not (in_bound o.bound r tmin 0) then false
  else if Array.length o.clip = 0 then raw_hit o r tmin h f
  else begin
    (* the unclipped surface's crossings past the box are all clipped
       away: the queries need not look for them *)
    let t = stop_at_box o r h in
    let got = first_accepted true o r tmin h f by_clip [||] 0 in
    if not got then h.t <- t;
    got
  end

(* POV-Ray's [bounded_by]: the object is looked at only by rays that
   meet every bounding object, or start inside it; its crossings are then
   taken wherever they are. *)
and in_bound bs r tmin i =
  i >= Array.length bs
  ||
  let b = Array.unsafe_get bs i in
  let lv = Scratch.get bound_scratch in
  let h, f = Scratch.push lv in
  h.t <- infinity;
  h.floor <- neg_infinity;
  let met =
    hit_s b r tmin h f
    ||
    (f.pt.ox <- r.ox;
     f.pt.oy <- r.oy;
     f.pt.oz <- r.oz;
     inside_s b f)
  in
  Scratch.pop lv;
  met && in_bound bs r tmin (i + 1)

(* [f.leaf] is written only when it changes, here and below: each write
   is a call of caml_modify *)
and raw_hit o r tmin h f =
  match o.geom with
  | Prim (Shape.Blob b) ->
      (* a blob's depth tolerance is a distance in the world: it reads
         the world ray as well *)
      let got = Blob.hit_s b (local o r f) r tmin h in
      if got && f.leaf != o then f.leaf <- o;
      got
  | Prim s ->
      let got = Shape.hit_s s (local o r f) tmin h in
      if got && f.leaf != o then f.leaf <- o;
      got
  | Union cs -> (
      match o.index with
      | None ->
          let any = ref false in
          for i = 0 to Array.length cs - 1 do
            let c = Array.unsafe_get cs i in
            if (not (box_missed c r tmin h.t)) && hit_s c r tmin h f then any := true
          done;
          !any
      | Some x ->
          let any = ref false in
          for i = 0 to Array.length x.unbounded - 1 do
            if hit_s (Array.unsafe_get x.unbounded i) r tmin h f then any := true
          done;
          let b = Bvh.nearest_s x.bvh r tmin h x.bounded f union_leaf in
          b || !any)
  | Intersection cs ->
      (* what it keeps lies in its box: its parts' queries stop at the
         box's far side (an unbounded surface, cut by a box, searches no
         further) *)
      let t = stop_at_box o r h in
      let got = csg cs r tmin h f by_intersection in
      if not got then h.t <- t;
      got
  | Merge cs -> csg cs r tmin h f by_merge

and union_leaf bounded f r tmin h i = hit_s (Array.unsafe_get bounded i) r tmin h f

(* Nearest crossing of child i kept by the rule [kind] (each child's
   surface crossings are walked nearest first until one is kept). *)
and csg cs r tmin h f kind =
  let any = ref false in
  for i = 0 to Array.length cs - 1 do
    let c = Array.unsafe_get cs i in
    if (not (box_missed c r tmin h.t)) && first_accepted false c r tmin h f kind cs i then any := true
  done;
  !any

(* The walk works in [h] itself, restoring it (and [f.leaf]) when no
   crossing is kept. [raw]: query [o] without its clip (the clip is the
   rule); otherwise [o] is child [i] of [cs]. *)
and first_accepted raw o r tmin h f kind cs i =
  let t0 = h.t and u0 = h.u and v0 = h.v and id0 = h.id and leaf0 = f.leaf and floor0 = h.floor in
  let result = ref false and go = ref true in
  while !go do
    (* each query passes [tmin] as it came (no float to box); the
       crossings passed are below [h.floor] *)
    let got = query raw o r tmin h f in
    if got then begin
      let t = h.t in
      let p = f.pt in
      p.ox <- r.ox +. (t *. r.dx);
      p.oy <- r.oy +. (t *. r.dy);
      p.oz <- r.oz +. (t *. r.dz);
      let ok =
        if kind = by_clip then all_inside o.clip f 0 (-1)
        else if kind = by_intersection then all_inside cs f 0 i
        else none_inside cs f 0 i
      in
      if ok then (
        result := true;
        go := false)
      else begin
        h.t <- t0;
        h.u <- u0;
        h.v <- v0;
        h.id <- id0;
        if f.leaf != leaf0 then f.leaf <- leaf0;
        h.floor <- next_tmin_s r t
      end
    end
    else go := false
  done;
  h.floor <- floor0;
  !result

and query raw o r tm h f = if raw then raw_hit o r tm h f else hit_s o r tm h f

let hit o r tmin h f = hit_s o (Ray.of_ray r) tmin h f

let intersect o r tmin tmax =
  let h = Hit.create tmax in
  if hit o r tmin h (found o) then h.t else infinity

(* A crossing of a mesh (no clip) in (tmin, r.far): the first one found *)
let any_mesh o m (r : Ray.scratch) tmin (h : Hit.t) (f : found) =
  h.t <- r.far;
  let got = Mesh.any_s m (local o r f) tmin h in
  if got && f.leaf != o then f.leaf <- o;
  got

(* [crossings_s o ray tmin h f shadow opaque g]: with [h] and [f] as
   scratch. A shadow ray through a mesh that [g] stops at wherever it is
   crossed ([opaque]) needs one crossing, not the nearest: an any-hit walk
   of the mesh's BVH. [g] is not called where [opaque] already answers.
   [g] reads the crossing's distance in [h] (passed, it would be boxed). *)
let crossings_s o (r : Ray.scratch) tmin (h : Hit.t) fd shadow opaque g =
  match o.geom with
  | _ when shadow && o.no_shadow ->
      (* every crossing would be passed over (a light's looks_like, a
         CSG of no_shadow parts) *)
      true
  | Prim (Shape.Mesh m) when shadow && Array.length o.clip = 0 && Array.length o.bound = 0 && opaque o ->
      not (any_mesh o m r tmin h fd)
  | _ ->
  let tmax = r.far and floor0 = h.floor in
  let ok = ref true and go = ref true in
  while !go do
    h.t <- tmax;
    (* [tmin] as it came, the crossings passed below [h.floor] *)
    if hit_s o r tmin h fd then begin
      let leaf = fd.leaf in
      if (shadow && leaf.no_shadow) || ((not (opaque leaf)) && g leaf h) then h.floor <- next_tmin_s r h.t
      else (
        ok := false;
        go := false)
    end
    else go := false
  done;
  h.floor <- floor0;
  !ok

let never _ = false

let crossings o r tmin tmax f =
  let s = Ray.of_ray r in
  s.far <- tmax;
  crossings_s o s tmin (Hit.create tmax) (found o) false never (fun leaf (h : Hit.t) -> f leaf h.t)

(* A leaf's world normal at [p], into [out]: nothing allocated *)
let normal_into o (p : Vec3.m) h out =
  match o.geom with
  | Prim s ->
      if Transform.is_identity o.xform then Shape.normal_into s p h out
      else begin
        Transform.inv_point_m o.xform p out;
        Shape.normal_into s out h out;
        Transform.normal_m o.xform out;
        Vec3.normalize_m out
      end;
      if o.inverted then Vec3.set out (-.out.mx) (-.out.my) (-.out.mz)
  | Union _ | Intersection _ | Merge _ -> invalid_arg "Object.normal: not a leaf"

let crossed_texture o (p : Vec3.m) h (r : Ray.scratch) (n : Vec3.m) =
  if o.back == o.texture then o.texture
  else begin
    normal_into o p h n;
    if (n.mx *. r.dx) +. (n.my *. r.dy) +. (n.mz *. r.dz) > 0. then o.back else o.texture
  end

let uv_into o (p : Vec3.m) h out =
  match o.geom with
  | Prim s ->
      if Transform.is_identity o.xform then Shape.uv_into s p h out
      else begin
        Transform.inv_point_m o.xform p out;
        Shape.uv_into s out h out
      end
  | Union _ | Intersection _ | Merge _ -> invalid_arg "Object.uv_into: not a leaf"

let normal o (p : Vec3.t) h =
  let pm = Vec3.m () and out = Vec3.m () in
  Vec3.load pm p;
  normal_into o pm h out;
  Vec3.of_m out

let bounds o = o.bounds
