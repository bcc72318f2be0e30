(* POV-Ray 3.7's mesh camera (CreateCameraRay, its MESH_CAMERA case):
   the faces are preprocessed once into flat arrays, so that a camera ray
   reads a few floats, applies the mesh's transform and allocates
   nothing. *)

type distribution = Per_mesh | Summed | Side_by_side | Uv_map

(* the uv lookup: a g x g grid over [0,1]^2 (coordinates outside it fall
   into the border cells), each cell listing, in increasing order, the
   faces whose uv box meets it; a point's cell lists every face whose uv
   triangle holds the point, so the first one found there is the first in
   index order (the rule POV-Ray's coarser 10 x 10 index gives too) *)
type grid = { g : int; start : int array; items : int array }

type mesh = {
  n : int;
  dropped : int;
  centre : Float.Array.t;  (* 3 a face: the centroid *)
  normal : Float.Array.t;  (* 3 a face: the unit face normal, single precision *)
  corner : Float.Array.t;  (* 9 a face (P1, P2, P3, single precision), or empty *)
  uv : Float.Array.t;  (* 6 a face (uv of P1, P2, P3), or empty *)
  vnormal : Float.Array.t;  (* 9 a face (unit normals at P1, P2, P3), nan for a flat face; or empty *)
  grid : grid;
}

let fget = Float.Array.unsafe_get
let fset = Float.Array.unsafe_set

(* the nearest single-precision value (POV-Ray keeps mesh vertices and
   normals in floats) *)
let single = Floats.single

(* the cell of a coordinate, for a grid of [g] cells a side *)
let[@inline] cell g c =
  let x = c *. float_of_int g in
  if not (x >= 0.) then 0 else if x >= float_of_int g then g - 1 else int_of_float x

(* twice the signed area of a face's uv triangle (POV-Ray's [scale]) *)
let[@inline] uv_area uv f =
  let o = 6 * f in
  let u1 = fget uv o and v1 = fget uv (o + 1) and u2 = fget uv (o + 2) and v2 = fget uv (o + 3)
  and u3 = fget uv (o + 4) and v3 = fget uv (o + 5) in
  ((u2 -. u1) *. (v3 -. v1)) -. ((u3 -. u1) *. (v2 -. v1))

let usable uv f =
  let s = uv_area uv f in
  s <> 0. && Float.is_finite s

let no_grid = { g = 1; start = [| 0; 0 |]; items = [||] }

let build_grid n uv =
  let g = max 1 (min 512 (int_of_float (Float.sqrt (float_of_int n)))) in
  let range f k =
    let a = fget uv ((6 * f) + k) and b = fget uv ((6 * f) + k + 2) and c = fget uv ((6 * f) + k + 4) in
    (cell g (Float.min a (Float.min b c)), cell g (Float.max a (Float.max b c)))
  in
  let visit fn =
    for f = 0 to n - 1 do
      if usable uv f then begin
        let i0, i1 = range f 0 and j0, j1 = range f 1 in
        for j = j0 to j1 do
          for i = i0 to i1 do
            fn ((j * g) + i) f
          done
        done
      end
    done
  in
  let start = Array.make ((g * g) + 1) 0 in
  visit (fun k _ -> start.(k + 1) <- start.(k + 1) + 1);
  for k = 1 to g * g do
    start.(k) <- start.(k) + start.(k - 1)
  done;
  let items = Array.make start.(g * g) 0 and fill = Array.sub start 0 (g * g) in
  visit (fun k f ->
      items.(fill.(k)) <- f;
      fill.(k) <- fill.(k) + 1);
  { g; start; items }

let mesh ~uv:with_uv ~verts ~faces ~normals ~normal_faces ~uvs ~uv_faces =
  let total = Array.length faces / 3 in
  let vert i c = Float.Array.get verts ((3 * i) + c) in
  (* POV-Ray's test for a degenerate face: |(P1 - P2) x (P3 - P2)| = 0 *)
  let keep f =
    let a = faces.(3 * f) and b = faces.((3 * f) + 1) and c = faces.((3 * f) + 2) in
    let d k = vert a k -. vert b k and e k = vert c k -. vert b k in
    let x = (d 1 *. e 2) -. (d 2 *. e 1) and y = (d 2 *. e 0) -. (d 0 *. e 2) and z = (d 0 *. e 1) -. (d 1 *. e 0) in
    Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) > 0.
  in
  let kept = List.filter keep (List.init total Fun.id) |> Array.of_list in
  let n = Array.length kept in
  let centre = Float.Array.create (3 * n) and normal = Float.Array.create (3 * n) in
  Array.iteri
    (fun j f ->
      let a = faces.(3 * f) and b = faces.((3 * f) + 1) and c = faces.((3 * f) + 2) in
      (* (P1 + P2 + P3) / 3 in single precision, as POV-Ray 3.7.0 sums
         and divides its float vertices *)
      for k = 0 to 2 do
        fset centre ((3 * j) + k)
          (single (single (single (single (vert a k) +. single (vert b k)) +. single (vert c k)) /. 3.))
      done;
      let d k = vert c k -. vert a k and e k = vert b k -. vert a k in
      let x = (d 1 *. e 2) -. (d 2 *. e 1) and y = (d 2 *. e 0) -. (d 0 *. e 2) and z = (d 0 *. e 1) -. (d 1 *. e 0) in
      let l = Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) in
      fset normal (3 * j) (single (x /. l));
      fset normal ((3 * j) + 1) (single (y /. l));
      fset normal ((3 * j) + 2) (single (z /. l)))
    kept;
  let corner, uv, vnormal =
    if not with_uv then (Float.Array.create 0, Float.Array.create 0, Float.Array.create 0)
    else begin
      let corner = Float.Array.create (9 * n) and uv = Float.Array.make (6 * n) 0. in
      let vnormal = Float.Array.make (9 * n) Float.nan in
      Array.iteri
        (fun j f ->
          for q = 0 to 2 do
            let p = faces.((3 * f) + q) in
            for k = 0 to 2 do
              fset corner ((9 * j) + (3 * q) + k) (single (vert p k))
            done;
            if Array.length uv_faces > 0 then begin
              let t = uv_faces.((3 * f) + q) in
              fset uv ((6 * j) + (2 * q)) (Float.Array.get uvs (2 * t));
              fset uv ((6 * j) + (2 * q) + 1) (Float.Array.get uvs ((2 * t) + 1))
            end
          done;
          let flat = Array.length normal_faces = 0 || Array.exists (fun q -> normal_faces.((3 * f) + q) < 0) [| 0; 1; 2 |] in
          if not flat then
            for q = 0 to 2 do
              let t = normal_faces.((3 * f) + q) in
              let g k = Float.Array.get normals ((3 * t) + k) in
              let l = Float.sqrt ((g 0 *. g 0) +. (g 1 *. g 1) +. (g 2 *. g 2)) in
              for k = 0 to 2 do
                fset vnormal ((9 * j) + (3 * q) + k) (single (g k /. l))
              done
            done)
        kept;
      (corner, uv, vnormal)
    end
  in
  let grid = if with_uv then build_grid n uv else no_grid in
  { n; dropped = total - n; centre; normal; corner; uv; vnormal; grid }

let faces m = m.n
let dropped m = m.dropped

let has_uv m =
  let rec go f = f < m.n && (usable m.uv f || go (f + 1)) in
  Float.Array.length m.uv > 0 && go 0

type t = {
  rays : int;
  far : float;  (* infinity: no limit *)
  distribution : distribution;
  smooth : bool;
  push : float;
  flip : bool;
  meshes : mesh array;
  xfs : Transform.t array;
  ends : int array;  (* the running total of faces after each mesh *)
}

let make ?(far = 0.) ~rays ~distribution ~smooth ~push ~flip ms =
  let meshes = Array.map fst ms and xfs = Array.map snd ms in
  let ends = Array.make (Array.length meshes) 0 in
  Array.iteri (fun i m -> ends.(i) <- (if i = 0 then 0 else ends.(i - 1)) + m.n) meshes;
  { rays; far = (if far > 0. then far else infinity); distribution; smooth; push; flip; meshes; xfs; ends }

let rays c = c.rays
let far c = c.far

(* the ray from the point in [o] along the normal in [d] (mesh space):
   moved [push] along the normal, turned round when [flip], then placed
   by the transform and normalised *)
let[@inline] finish c xf (o : Vec3.m) (d : Vec3.m) =
  let k = c.push in
  Vec3.set o (o.mx +. (k *. d.mx)) (o.my +. (k *. d.my)) (o.mz +. (k *. d.mz));
  if c.flip then Vec3.set d (-.d.mx) (-.d.my) (-.d.mz);
  Transform.point_m xf o o;
  Transform.normal_m xf d;
  Vec3.normalize_m d

(* face [f] of mesh [i]: from its centroid along its normal *)
let face_ray c i f o d =
  let m = c.meshes.(i) and b = 3 * f in
  Vec3.set o (fget m.centre b) (fget m.centre (b + 1)) (fget m.centre (b + 2));
  Vec3.set d (fget m.normal b) (fget m.normal (b + 1)) (fget m.normal (b + 2));
  finish c c.xfs.(i) o d;
  true

(* POV-Ray's barycentric weights of (u, v) in face [f]'s uv triangle:
   the face holds the point when all three are >= 0; they are written
   into [d] *)
let[@inline] weights m f u v (d : Vec3.m) =
  let uv = m.uv and o = 6 * f in
  let u1 = fget uv o and v1 = fget uv (o + 1) and u2 = fget uv (o + 2) and v2 = fget uv (o + 3)
  and u3 = fget uv (o + 4) and v3 = fget uv (o + 5) in
  let s = ((u2 -. u1) *. (v3 -. v1)) -. ((u3 -. u1) *. (v2 -. v1)) in
  let b1 = (((u2 -. u) *. (v3 -. v)) -. ((u3 -. u) *. (v2 -. v))) /. s
  and b2 = (((u3 -. u) *. (v1 -. v)) -. ((u1 -. u) *. (v3 -. v))) /. s
  and b3 = (((u1 -. u) *. (v2 -. v)) -. ((u2 -. u) *. (v1 -. v))) /. s in
  Vec3.set d b1 b2 b3;
  not (b1 < 0. || b2 < 0. || b3 < 0.)

(* [a.(o) b1 + a.(o+3) b2 + a.(o+6) b3] for the 3 components, into [out] *)
let[@inline] blend a o b1 b2 b3 (out : Vec3.m) =
  Vec3.set out
    ((b1 *. fget a o) +. (b2 *. fget a (o + 3)) +. (b3 *. fget a (o + 6)))
    ((b1 *. fget a (o + 1)) +. (b2 *. fget a (o + 4)) +. (b3 *. fget a (o + 7)))
    ((b1 *. fget a (o + 2)) +. (b2 *. fget a (o + 5)) +. (b3 *. fget a (o + 8)))

(* distribution 3: the first face of mesh 0 whose uv triangle holds
   (u, v) = ((x - 0.5) / width, 1 - (y + 0.5) / height), for POV-Ray's
   point (x, y) (in [o]'s x and y; see [ray_into]) *)
let uv_ray c ~width ~height (o : Vec3.m) (d : Vec3.m) =
  let m = c.meshes.(0) and gr = c.meshes.(0).grid in
  let u = (o.mx -. 0.5) /. float_of_int width and v = 1. -. ((o.my +. 0.5) /. float_of_int height) in
  let k = (cell gr.g v * gr.g) + cell gr.g u in
  let last = gr.start.(k + 1) in
  let i = ref gr.start.(k) in
  while !i < last && not (weights m gr.items.(!i) u v d) do
    incr i
  done;
  if !i >= last then false
  else begin
    let f = gr.items.(!i) in
    let b1 = d.mx and b2 = d.my and b3 = d.mz in
    blend m.corner (9 * f) b1 b2 b3 o;
    (* with smooth, the corners' normals blended by the same weights,
       not normalised (POV-Ray's Smooth_Mesh_Normal: the push uses it as
       it is) *)
    if c.smooth && not (Float.is_nan (fget m.vnormal (9 * f))) then blend m.vnormal (9 * f) b1 b2 b3 d
    else Vec3.set d (fget m.normal (3 * f)) (fget m.normal ((3 * f) + 1)) (fget m.normal ((3 * f) + 2));
    finish c c.xfs.(0) o d;
    true
  end

(* [p] clamped to [0, n - 1] *)
let[@inline] clamp p n = if not (p >= 0.) then 0. else if p > float_of_int (n - 1) then float_of_int (n - 1) else p

(* POV-Ray 3.7.0 is handed the image point less half a pixel each way
   (pixel (i, j) as (i, j)), moves it by (+0.5, -0.5) ("to the centre of
   the pixel", right for x, wrong way for y) and clamps it to the image:
   from camlray's image point (px, py) that is (px, py - 1), clamped.
   Measured with POV-Ray 3.7.0.10: row j of the image takes faces of
   row j - 1 (row 0 too), and distribution 3 reads u = i / width, v = 1
   - j / height, but (width - 1.5) / width in the last column and 1 -
   0.5 / height in the first row. POV-Ray 3.7.1 takes the point as it
   is (floored for distributions 0 to 2, not clamped for 3). *)
let ray_into c ~width ~height k (o : Vec3.m) (d : Vec3.m) =
  let x = clamp o.mx width and y = clamp (o.my -. 1.) height in
  match c.distribution with
  | Uv_map ->
      Vec3.set o x y 0.;
      uv_ray c ~width ~height o d
  | Per_mesh | Summed | Side_by_side -> (
      let col = int_of_float x and row = int_of_float y in
      let pixel = (row * width) + col in
      match c.distribution with
      | Per_mesh -> pixel < c.meshes.(k).n && face_ray c k pixel o d
      | Summed ->
          let total = c.ends.(Array.length c.ends - 1) in
          let f = pixel + (k * total) in
          f < total
          &&
          let i = ref 0 in
          while c.ends.(!i) <= f do
            incr i
          done;
          face_ray c !i (f - if !i = 0 then 0 else c.ends.(!i - 1)) o d
      | Side_by_side | Uv_map ->
          (* the strip [x / (width / meshes)], divided in floats; the
             face [row * (width / meshes) + col], in integers, the column
             counted from the image's left edge (POV-Ray's rule) *)
          let nm = Array.length c.meshes in
          let i = int_of_float (x /. (float_of_int width /. float_of_int nm)) in
          let f = (row * (width / nm)) + col in
          i < nm && f < c.meshes.(i).n && face_ray c i f o d)
