(* Triangles are stored in BVH leaf order, 9 floats each (the three
   corners), so a leaf's triangles are contiguous in memory; [nfaces] (3
   normal indices per triangle, or empty) follows the same order. The
   corners are single precision, as POV-Ray 3.7 stores mesh vertices
   (MeshVector is a SnglVector3d): 36 bytes a triangle instead of 72, the
   test itself in double. *)
type f32 = (float, Bigarray.float32_elt, Bigarray.c_layout) Bigarray.Array1.t

type t = {
  tris : f32;
  normals : Float.Array.t;
  nfaces : int array;
  bvh : Bvh.t;
  inside_vector : Vec3.t option;
  uvs : Float.Array.t;  (* u, v of each corner (6 a triangle, BVH order), or empty: all <0, 0> *)
}

let fget = Float.Array.unsafe_get
let tget (a : f32) i = Bigarray.Array1.unsafe_get a i

(* the nearest single-precision value *)
let single = Floats.single

let[@inline] tri_hit ax ay az bx by bz cx cy cz (r : Ray.scratch) tmin (h : Hit.t) =
  let e1x = bx -. ax and e1y = by -. ay and e1z = bz -. az in
  let e2x = cx -. ax and e2y = cy -. ay and e2z = cz -. az in
  let dx = r.dx and dy = r.dy and dz = r.dz in
  let px = (dy *. e2z) -. (dz *. e2y) and py = (dz *. e2x) -. (dx *. e2z)
  and pz = (dx *. e2y) -. (dy *. e2x) in
  let det = (e1x *. px) +. (e1y *. py) +. (e1z *. pz) in
  if det = 0. then false
  else
    let inv = 1. /. det in
    let sx = r.ox -. ax and sy = r.oy -. ay and sz = r.oz -. az in
    let u = ((sx *. px) +. (sy *. py) +. (sz *. pz)) *. inv in
    if u < 0. || u > 1. then false
    else
      let qx = (sy *. e1z) -. (sz *. e1y) and qy = (sz *. e1x) -. (sx *. e1z)
      and qz = (sx *. e1y) -. (sy *. e1x) in
      let v = ((dx *. qx) +. (dy *. qy) +. (dz *. qz)) *. inv in
      if v < 0. || u +. v > 1. then false
      else
        let t = ((e2x *. qx) +. (e2y *. qy) +. (e2z *. qz)) *. inv in
        if t > tmin && t > h.floor && t < h.t then (
          h.t <- t;
          h.u <- u;
          h.v <- v;
          true)
        else false

(* [x, y, z] / |[x, y, z]| as [Vec3.normalize], into [out] *)
let[@inline] unit_into (out : Vec3.m) x y z =
  Vec3.set out x y z;
  Vec3.normalize_m out

(* w n1 + u n2 + v n3, normalised, from the nine components *)
let[@inline] blend3 out ax ay az bx by bz cx cy cz u v =
  let w = 1. -. u -. v in
  unit_into out
    ((w *. ax) +. (u *. bx) +. (v *. cx))
    ((w *. ay) +. (u *. by) +. (v *. cy))
    ((w *. az) +. (u *. bz) +. (v *. cz))

let smooth_normal_into (n1 : Vec3.t) (n2 : Vec3.t) (n3 : Vec3.t) (h : Hit.t) out =
  blend3 out n1.x n1.y n1.z n2.x n2.y n2.z n3.x n3.y n3.z h.u h.v

let smooth_normal (n1 : Vec3.t) (n2 : Vec3.t) (n3 : Vec3.t) u v =
  let out = Vec3.m () in
  blend3 out n1.x n1.y n1.z n2.x n2.y n2.z n3.x n3.y n3.z u v;
  Vec3.of_m out


let make ?uv ~par ~verts ~normals ~faces ~normal_faces ~inside_vector () =
  let verts = Float.Array.map single verts in
  let normals = Float.Array.copy normals in
  for i = 0 to (Float.Array.length normals / 3) - 1 do
    let g k = Float.Array.get normals ((3 * i) + k) in
    let l = Float.sqrt ((g 0 *. g 0) +. (g 1 *. g 1) +. (g 2 *. g 2)) in
    if l > 0. then for k = 0 to 2 do Float.Array.set normals ((3 * i) + k) (g k /. l) done
  done;
  let n = Array.length faces / 3 in
  let smooth = Array.length normal_faces > 0 in
  let v = verts in
  (* degenerate faces are dropped (in scalars: this runs over every face
     of a mesh of millions before its BVH is built) *)
  let g i c = fget v ((3 * i) + c) in
  let kept = Bytes.make n '\000' and k = ref 0 in
  for i = 0 to n - 1 do
    let a = faces.(3 * i) and b = faces.((3 * i) + 1) and c = faces.((3 * i) + 2) in
    let ax = g a 0 and ay = g a 1 and az = g a 2 in
    let ux = g b 0 -. ax and uy = g b 1 -. ay and uz = g b 2 -. az in
    let wx = g c 0 -. ax and wy = g c 1 -. ay and wz = g c 2 -. az in
    let cx = (uy *. wz) -. (uz *. wy) and cy = (uz *. wx) -. (ux *. wz) and cz = (ux *. wy) -. (uy *. wx) in
    if (cx *. cx) +. (cy *. cy) +. (cz *. cz) > 0. && Float.is_finite cx && Float.is_finite cy && Float.is_finite cz
    then begin
      Bytes.unsafe_set kept i '\001';
      incr k
    end
  done;
  let k = !k in
  let keep = Array.make k 0 in
  let j = ref 0 in
  for i = 0 to n - 1 do
    if Bytes.unsafe_get kept i = '\001' then begin
      keep.(!j) <- i;
      incr j
    end
  done;
  let faces' = Array.make (3 * k) 0 in
  let nfaces' = if smooth then Array.make (3 * k) (-1) else [||] in
  let boxes = Float.Array.create (6 * k) in
  for j = 0 to k - 1 do
    let i = keep.(j) in
    for c = 0 to 2 do
      faces'.((3 * j) + c) <- faces.((3 * i) + c);
      if smooth then nfaces'.((3 * j) + c) <- normal_faces.((3 * i) + c)
    done;
    let a = faces'.(3 * j) and b = faces'.((3 * j) + 1) and c = faces'.((3 * j) + 2) in
    for q = 0 to 2 do
      (* a kept face's corners are finite (its cross product is): no
         NaN to order, and a zero's sign does not move a box *)
      let x = g a q and y = g b q and z = g c q in
      let lo = if x < y then x else y and hi = if x > y then x else y in
      Float.Array.set boxes ((6 * j) + q) (if z < lo then z else lo);
      Float.Array.set boxes ((6 * j) + 3 + q) (if z > hi then z else hi)
    done
  done;
  let bvh, order = Bvh.renumber (Bvh.build ?par boxes) in
  let tris = Bigarray.Array1.create Bigarray.float32 Bigarray.c_layout (9 * k) in
  Array.iteri
    (fun j i ->
      for c = 0 to 2 do
        let p = faces'.((3 * i) + c) in
        for q = 0 to 2 do
          tris.{(9 * j) + (3 * c) + q} <- g p q
        done
      done)
    order;
  let nfaces = if smooth then Array.init (3 * k) (fun q -> nfaces'.((3 * order.(q / 3)) + (q mod 3))) else [||] in
  let uvs =
    match uv with
    | None -> Float.Array.create 0
    | Some (coords, uv_faces) ->
        let a = Float.Array.create (6 * k) in
        Array.iteri
          (fun j i ->
            for c = 0 to 2 do
              let q = uv_faces.((3 * keep.(i)) + c) in
              Float.Array.set a ((6 * j) + (2 * c)) (Float.Array.get coords (2 * q));
              Float.Array.set a ((6 * j) + (2 * c) + 1) (Float.Array.get coords ((2 * q) + 1))
            done)
          order;
        a
  in
  { tris; normals; nfaces; bvh; inside_vector; uvs }

let uv_into m (h : Hit.t) (out : Vec3.m) =
  if Float.Array.length m.uvs = 0 then Vec3.set out 0. 0. 0.
  else begin
    let i = 6 * int_of_float h.id and a = m.uvs in
    let wb = h.u and wc = h.v in
    let wa = 1. -. wb -. wc in
    Vec3.set out
      ((wa *. fget a i) +. (wb *. fget a (i + 2)) +. (wc *. fget a (i + 4)))
      ((wa *. fget a (i + 1)) +. (wb *. fget a (i + 3)) +. (wc *. fget a (i + 5)))
      0.
  end

let triangles m = Bigarray.Array1.dim m.tris / 9

let bytes m =
  (4 * Bigarray.Array1.dim m.tris)
  + (8 * (Float.Array.length m.normals + Array.length m.nfaces))
  + Bvh.bytes m.bvh

let bounds m =
  match Bvh.bounds m.bvh with Some b -> b | None -> (Vec3.zero, Vec3.zero)

let[@inline] tri m i r tmin h =
  let p = m.tris in
  let a = 9 * i in
  let b = a + 3 and c = a + 6 in
  tri_hit (tget p a) (tget p (a + 1)) (tget p (a + 2)) (tget p b) (tget p (b + 1)) (tget p (b + 2))
    (tget p c) (tget p (c + 1)) (tget p (c + 2)) r tmin h

let leaf m () r tmin (h : Hit.t) i =
  if tri m i r tmin h then (
    h.id <- float i;
    true)
  else false

let hit_s m r tmin h = Bvh.nearest_s m.bvh r tmin h m () leaf

(* the walk goes on while no triangle is hit *)
let any_leaf m h r tmin i = not (leaf m () r tmin h i)

let any_s m (r : Ray.scratch) tmin (h : Hit.t) =
  r.far <- h.t;
  not (Bvh.iter_s m.bvh r tmin m h any_leaf)
let hit m r tmin h = hit_s m (Ray.of_ray r) tmin h

(* The hit's normal into [out], in scalars (the same arithmetic as
   [Vec3.normalize (Vec3.cross (b - a) (c - a))] and [smooth_normal]). *)
let normal_into m (h : Hit.t) out =
  let i = int_of_float h.id in
  let na = if Array.length m.nfaces > 0 then m.nfaces.(3 * i) else -1 in
  if na >= 0 then begin
    let g = m.normals and nb = m.nfaces.((3 * i) + 1) and nc = m.nfaces.((3 * i) + 2) in
    blend3 out
      (fget g (3 * na)) (fget g ((3 * na) + 1)) (fget g ((3 * na) + 2))
      (fget g (3 * nb)) (fget g ((3 * nb) + 1)) (fget g ((3 * nb) + 2))
      (fget g (3 * nc)) (fget g ((3 * nc) + 1)) (fget g ((3 * nc) + 2))
      h.u h.v
  end
  else begin
    let t = m.tris and o = 9 * i in
    let ax = tget t o and ay = tget t (o + 1) and az = tget t (o + 2) in
    let ux = tget t (o + 3) -. ax and uy = tget t (o + 4) -. ay and uz = tget t (o + 5) -. az in
    let vx = tget t (o + 6) -. ax and vy = tget t (o + 7) -. ay and vz = tget t (o + 8) -. az in
    unit_into out ((uy *. vz) -. (uz *. vy)) ((uz *. vx) -. (ux *. vz)) ((ux *. vy) -. (uy *. vx))
  end

let normal m h =
  let out = Vec3.m () in
  normal_into m h out;
  Vec3.of_m out

let inside m p =
  match m.inside_vector with
  | None -> false
  | Some d ->
      let r = Ray.of_ray (Ray.make p d) in
      let count = ref 0 in
      let h = Hit.create infinity in
      ignore
        (Bvh.iter_s m.bvh r 0. () () (fun () () _ _ i ->
             h.t <- infinity;
             if tri m i r 0. h then incr count;
             true));
      !count land 1 = 1

(* no point made when there is no inside vector (inside tests of meshes
   in CSG and object patterns ask at every crossing) *)
let[@inline] inside_xyz m x y z =
  match m.inside_vector with None -> false | Some _ -> inside m (Vec3.make x y z)
