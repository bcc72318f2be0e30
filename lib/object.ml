type t = {
  geom : geom;
  xform : Transform.t;
  texture : Texture.t;
  interior : Interior.t;
  no_shadow : bool;
  inverted : bool;
  clip : t array;
  bounds : (Vec3.t * Vec3.t) option;
  index : index option;
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

(* Bounds of where [inside] can be true (a disc's inside is a half-space,
   wider than its surface): what intersections and clips may trust. *)
let rec solid_box o =
  match o.geom with
  | Prim (Shape.Disc _) -> None
  | Prim _ | Intersection _ -> o.bounds
  | Union cs | Merge cs ->
      if Array.length cs = 0 then o.bounds
      else Array.fold_left (fun b c -> box_union b (solid_box c)) (solid_box cs.(0)) cs

let clip_box clip b = Array.fold_left (fun b c -> box_inter b (solid_box c)) b clip

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

let make ?(xform = Transform.identity) ?(texture = Texture.default) ?(interior = Interior.default)
    ?(no_shadow = false) ?(inverted = false) ?(clip = [||]) shape =
  let xform, shape = fold xform shape in
  let b = if inverted then None else world_box xform (Shape.bounds shape) in
  { geom = Prim shape; xform; texture; interior; no_shadow; inverted; clip; bounds = clip_box clip b; index = None }

let node geom clip b =
  {
    geom;
    xform = Transform.identity;
    texture = Texture.default;
    interior = Interior.default;
    no_shadow = false;
    inverted = false;
    clip;
    bounds = clip_box clip b;
    index = None;
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

let intersection ?(clip = [||]) cs =
  node (Intersection cs) clip (Array.fold_left (fun b c -> box_inter b (solid_box c)) None cs)

let with_clip o clip =
  let clip = Array.append o.clip clip in
  { o with clip; bounds = clip_box clip o.bounds }

let rec invert o =
  match o.geom with
  | Prim s ->
      let b = if o.inverted then world_box o.xform (Shape.bounds s) else None in
      { o with inverted = not o.inverted; bounds = clip_box o.clip b }
  | Union cs | Merge cs -> intersection ~clip:o.clip (Array.map invert cs)
  | Intersection cs -> merge ~clip:o.clip (Array.map invert cs)

type found = { mutable leaf : t }

let found o = { leaf = o }

let next_tmin (r : Ray.t) t =
  let dl = Vec3.length r.dir in
  let step = 1e-9 *. (1. +. (Float.abs t *. dl)) /. dl in
  Float.max (t +. step) (Float.succ t)

let rec inside o p =
  let raw =
    match o.geom with
    | Prim s ->
        let q = if Transform.is_identity o.xform then p else Transform.inv_point o.xform p in
        Shape.inside s q <> o.inverted
    | Union cs | Merge cs -> Array.exists (fun c -> inside c p) cs
    | Intersection cs -> Array.for_all (fun c -> inside c p) cs
  in
  raw && Array.for_all (fun c -> inside c p) o.clip

let others_all cs i p pred =
  let ok = ref true and j = ref 0 in
  while !ok && !j < Array.length cs do
    if !j <> i && not (pred cs.(!j) p) then ok := false;
    incr j
  done;
  !ok

(* Whether the ray misses the object's box within (tmin, tmax). *)
let box_missed o (r : Ray.t) tmin tmax =
  match o.bounds with
  | None -> false
  | Some ((lo : Vec3.t), (hi : Vec3.t)) ->
      let t0 = ref tmin and t1 = ref tmax in
      let slab o d l u =
        if d = 0. then (if o < l || o > u then t1 := neg_infinity)
        else
          let a = (l -. o) /. d and b = (u -. o) /. d in
          if a < b then (if a > !t0 then t0 := a; if b < !t1 then t1 := b)
          else (if b > !t0 then t0 := b; if a < !t1 then t1 := a)
      in
      slab r.origin.x r.dir.x lo.x hi.x;
      slab r.origin.y r.dir.y lo.y hi.y;
      slab r.origin.z r.dir.z lo.z hi.z;
      !t0 > !t1

let rec hit o (r : Ray.t) tmin (h : Hit.t) f =
  if Array.length o.clip = 0 then raw_hit o r tmin h f
  else first_accepted raw_hit o r tmin h f (fun p -> Array.for_all (fun c -> inside c p) o.clip)

and raw_hit o r tmin h f =
  match o.geom with
  | Prim s ->
      let r = if Transform.is_identity o.xform then r else
          Ray.make (Transform.inv_point o.xform r.origin) (Transform.inv_vector o.xform r.dir) in
      if Shape.hit s r tmin h then (
        f.leaf <- o;
        true)
      else false
  | Union cs -> (
      let any = ref false in
      match o.index with
      | None ->
          for i = 0 to Array.length cs - 1 do
            if (not (box_missed cs.(i) r tmin h.t)) && hit cs.(i) r tmin h f then any := true
          done;
          !any
      | Some x ->
          Array.iter (fun c -> if hit c r tmin h f then any := true) x.unbounded;
          Bvh.nearest x.bvh r tmin h (fun i -> if hit (Array.unsafe_get x.bounded i) r tmin h f then any := true);
          !any)
  | Intersection cs -> csg cs r tmin h f (fun i p -> others_all cs i p inside)
  | Merge cs -> csg cs r tmin h f (fun i p -> others_all cs i p (fun c p -> not (inside c p)))

(* Nearest crossing of child i kept by [keep i] (each child's surface
   crossings are walked nearest first until one is kept). *)
and csg cs r tmin h f keep =
  let any = ref false in
  for i = 0 to Array.length cs - 1 do
    if (not (box_missed cs.(i) r tmin h.t)) && first_accepted hit cs.(i) r tmin h f (keep i) then any := true
  done;
  !any

and first_accepted query o r tmin h f accept =
  let tmp = Hit.create h.t and tf = found o in
  let t0 = ref tmin and result = ref false and go = ref true in
  while !go do
    tmp.t <- h.t;
    if query o r !t0 tmp tf then
      if accept (Ray.at r tmp.t) then (
        Hit.copy_into tmp h;
        f.leaf <- tf.leaf;
        result := true;
        go := false)
      else t0 := next_tmin r tmp.t
    else go := false
  done;
  !result

let intersect o r tmin tmax =
  let h = Hit.create tmax in
  if hit o r tmin h (found o) then h.t else infinity

let crossings o r tmin tmax f =
  let h = Hit.create tmax and fd = found o in
  let rec go t0 =
    h.t <- tmax;
    if hit o r t0 h fd then f fd.leaf h.t && go (next_tmin r h.t) else true
  in
  go tmin

let normal o p h =
  match o.geom with
  | Prim s ->
      let n =
        if Transform.is_identity o.xform then Shape.normal s p h
        else Vec3.normalize (Transform.normal o.xform (Shape.normal s (Transform.inv_point o.xform p) h))
      in
      if o.inverted then Vec3.neg n else n
  | Union _ | Intersection _ | Merge _ -> invalid_arg "Object.normal: not a leaf"

let bounds o = o.bounds
