(* Blobs (see blob.mli). *)

type component =
  | Sphere of { center : Vec3.t; radius : float; strength : float }
  | Cylinder of { a : Vec3.t; b : Vec3.t; radius : float; strength : float }
  | Placed of { shape : component; xform : Transform.t }

let place xform = function
  | Placed { shape; xform = x } -> Placed { shape; xform = Transform.then_ x xform }
  | c -> Placed { shape = c; xform }

(* [comps]: a placed component holds a sphere or a cylinder; [inv]: 12
   floats per component, the inverse of a placed one's transform (blob
   space to its own), 3x4 row-major with the translation last (zeros for
   the others) *)
type t = { threshold : float; comps : component array; inv : Float.Array.t }

let inverse_into inv o xf =
  let c0 = Transform.inv_vector xf Vec3.unit_x and c1 = Transform.inv_vector xf Vec3.unit_y
  and c2 = Transform.inv_vector xf Vec3.unit_z and t = Transform.inv_point xf Vec3.zero in
  List.iteri (fun i x -> Float.Array.set inv (o + i) x)
    [ c0.x; c1.x; c2.x; c0.y; c1.y; c2.y; c0.z; c1.z; c2.z; t.x; t.y; t.z ]

(* a placed component of a placed component: one placement *)
let rec flat = function
  | Placed { shape = Placed { shape; xform = x }; xform } -> flat (Placed { shape; xform = Transform.then_ x xform })
  | c -> c

let make ~threshold comps =
  let comps = Array.of_list (List.map flat comps) in
  let inv = Float.Array.make (12 * Array.length comps) 0. in
  Array.iteri (fun i c -> match c with Placed { xform; _ } -> inverse_into inv (12 * i) xform | _ -> ()) comps;
  { threshold; comps; inv }

let components b = Array.length b.comps

(* if-based max: Float.max is a call that boxes its floats *)
let[@inline] fmax (a : float) b = if a >= b then a else b

(* not recursive, so that they are inlined (a float returned by a call is
   boxed) *)
let[@inline] radius = function
  | Sphere { radius; _ } | Cylinder { radius; _ } -> radius
  | Placed { shape = Sphere { radius; _ } | Cylinder { radius; _ }; _ } -> radius
  | Placed { shape = Placed _; _ } -> 0.

let[@inline] strength = function
  | Sphere { strength; _ } | Cylinder { strength; _ } -> strength
  | Placed { shape = Sphere { strength; _ } | Cylinder { strength; _ }; _ } -> strength
  | Placed { shape = Placed _; _ } -> 0.

(* the squared distance from (x, y, z) to a sphere or cylinder, and the
   nearest point of it, into [q] *)
let[@inline] dist2 c x y z (q : Vec3.m) =
  match c with
  | Sphere { center = p; _ } ->
      Vec3.set q p.x p.y p.z;
      let dx = x -. p.x and dy = y -. p.y and dz = z -. p.z in
      (dx *. dx) +. (dy *. dy) +. (dz *. dz)
  | Cylinder { a; b; _ } ->
      let wx = b.x -. a.x and wy = b.y -. a.y and wz = b.z -. a.z in
      let l2 = (wx *. wx) +. (wy *. wy) +. (wz *. wz) in
      let ex = x -. a.x and ey = y -. a.y and ez = z -. a.z in
      let s = ((ex *. wx) +. (ey *. wy) +. (ez *. wz)) /. l2 in
      let s = if s < 0. then 0. else if s > 1. then 1. else s in
      Vec3.set q (a.x +. (s *. wx)) (a.y +. (s *. wy)) (a.z +. (s *. wz));
      let dx = x -. q.mx and dy = y -. q.my and dz = z -. q.mz in
      (dx *. dx) +. (dy *. dy) +. (dz *. dz)
  | Placed _ -> infinity

(* Per domain: the nearest point of a component, and a point in a placed
   component's own space *)
type near = { q : Vec3.m; l : Vec3.m }

let near_key = Scratch.key (fun () -> { q = Vec3.m (); l = Vec3.m () })
let fget = Float.Array.unsafe_get

(* [(x, y, z)] in the own space of the placed component [i], into [l] *)
let[@inline] to_local b i x y z (l : Vec3.m) =
  let m = b.inv and o = 12 * i in
  Vec3.set l
    ((fget m o *. x) +. (fget m (o + 1) *. y) +. (fget m (o + 2) *. z) +. fget m (o + 9))
    ((fget m (o + 3) *. x) +. (fget m (o + 4) *. y) +. (fget m (o + 5) *. z) +. fget m (o + 10))
    ((fget m (o + 6) *. x) +. (fget m (o + 7) *. y) +. (fget m (o + 8) *. z) +. fget m (o + 11))

(* the squared distance from (x, y, z) (blob space) to component [i] in
   its own space: the nearest point in [nr.q], the point in [nr.l] *)
let[@inline] comp_dist2 b i c x y z nr =
  match c with
  | Placed { shape; _ } ->
      to_local b i x y z nr.l;
      dist2 shape nr.l.mx nr.l.my nr.l.mz nr.q
  | _ ->
      Vec3.set nr.l x y z;
      dist2 c x y z nr.q

let field b x y z =
  let nr = Scratch.get near_key in
  let sum = ref 0. in
  for i = 0 to Array.length b.comps - 1 do
    let c = Array.unsafe_get b.comps i in
    let r2 = radius c *. radius c in
    let d2 = comp_dist2 b i c x y z nr in
    if d2 < r2 then begin
      let u = 1. -. (d2 /. r2) in
      sum := !sum +. (strength c *. u *. u)
    end
  done;
  !sum

let inside b x y z = field b x y z > b.threshold

let normal_into b (p : Vec3.m) (out : Vec3.m) =
  let nr = Scratch.get near_key in
  let q = nr.q and l = nr.l in
  let x = p.mx and y = p.my and z = p.mz in
  let gx = ref 0. and gy = ref 0. and gz = ref 0. in
  for i = 0 to Array.length b.comps - 1 do
    let c = Array.unsafe_get b.comps i in
    let r2 = radius c *. radius c in
    let d2 = comp_dist2 b i c x y z nr in
    if d2 < r2 then begin
      (* the field falls away from the component: the gradient of
         -s (1 - d^2/r^2)^2 is 4 s (1 - d^2/r^2) (p - q) / r^2, in the
         component's own space; a placed component's is brought to the
         blob's by the transpose of its inverse's linear part *)
      let k = 4. *. strength c *. (1. -. (d2 /. r2)) /. r2 in
      let lx = k *. (l.mx -. q.mx) and ly = k *. (l.my -. q.my) and lz = k *. (l.mz -. q.mz) in
      match c with
      | Placed _ ->
          let m = b.inv and o = 12 * i in
          gx := !gx +. ((fget m o *. lx) +. (fget m (o + 3) *. ly) +. (fget m (o + 6) *. lz));
          gy := !gy +. ((fget m (o + 1) *. lx) +. (fget m (o + 4) *. ly) +. (fget m (o + 7) *. lz));
          gz := !gz +. ((fget m (o + 2) *. lx) +. (fget m (o + 5) *. ly) +. (fget m (o + 8) *. lz))
      | _ ->
          gx := !gx +. lx;
          gy := !gy +. ly;
          gz := !gz +. lz
    end
  done;
  (* no component reaches [p] (a crossing of a stretch clamped to start
     at 0, see [add_piece]): +x, as POV-Ray's Blob::Normal *)
  if !gx = 0. && !gy = 0. && !gz = 0. then Vec3.set out 1. 0. 0.
  else begin
    Vec3.set out !gx !gy !gz;
    Vec3.normalize_m out
  end

let weights b (p : Vec3.m) (ws : Float.Array.t) (ix : int array) =
  let nr = Scratch.get near_key in
  let n = ref 0 and sum = ref 0. in
  for i = 0 to Array.length b.comps - 1 do
    let c = Array.unsafe_get b.comps i in
    let r2 = radius c *. radius c in
    let d2 = comp_dist2 b i c p.mx p.my p.mz nr in
    if d2 < r2 then begin
      let u = 1. -. (d2 /. r2) in
      let f = Float.abs (strength c *. u *. u) in
      if f > 0. then begin
        Float.Array.set ws !n f;
        ix.(!n) <- i;
        sum := !sum +. f;
        incr n
      end
    end
  done;
  for j = 0 to !n - 1 do
    Float.Array.set ws j (Float.Array.get ws j /. !sum)
  done;
  !n

(* a sphere or cylinder's box in its own space *)
let own_box = function
  | Sphere { center; radius = r; _ } ->
      let e = Vec3.make r r r in
      (Vec3.sub center e, Vec3.add center e)
  | Cylinder { a; b; radius = r; _ } ->
      let e = Vec3.make r r r in
      (Vec3.sub (Vec3.min a b) e, Vec3.add (Vec3.max a b) e)
  | Placed _ -> (Vec3.zero, Vec3.zero)

let bounds b =
  let box = ref None in
  let add (lo : Vec3.t) (hi : Vec3.t) =
    box := Some (match !box with None -> (lo, hi) | Some (l, h) -> (Vec3.min l lo, Vec3.max h hi))
  in
  Array.iter
    (fun c ->
      if strength c > 0. then
        match c with
        | Placed { shape; xform } ->
            let (lo : Vec3.t), (hi : Vec3.t) = own_box shape in
            List.iter
              (fun (x, y, z) ->
                let p = Transform.point xform (Vec3.make x y z) in
                add p p)
              [ (lo.x, lo.y, lo.z); (hi.x, lo.y, lo.z); (lo.x, hi.y, lo.z); (hi.x, hi.y, lo.z);
                (lo.x, lo.y, hi.z); (hi.x, lo.y, hi.z); (lo.x, hi.y, hi.z); (hi.x, hi.y, hi.z) ]
        | _ ->
            let lo, hi = own_box c in
            add lo hi)
    b.comps;
  !box

(* {2 Along a ray} *)

(* Per domain: the stretches where components count (7 floats each: from,
   to, and the quartic's coefficients, constant first), the stretches'
   ends sorted, the quartic summed over a stretch. *)
type work = {
  mutable pieces : Float.Array.t;
  mutable n : int;
  mutable ends : Float.Array.t;
  sum : Float.Array.t;
  roots : Poly.scratch;
  dir : Vec3.m;  (* the ray's unit direction *)
  lo : Vec3.m;  (* a placed component's own space: the ray's origin ... *)
  ld : Vec3.m;  (* ... and its unit direction there (no longer unit) *)
}

let work_key =
  Scratch.key (fun () ->
      { pieces = Float.Array.make 70 0.; n = 0; ends = Float.Array.make 20 0.; sum = Float.Array.make 5 0.;
        roots = Poly.scratch 4; dir = Vec3.m (); lo = Vec3.m (); ld = Vec3.m () })

(* POV-Ray's DEPTH_TOLERANCE for blobs (blob.cpp): no crossing this
   near the ray's origin, in the world's units, is taken ([hit_s]); and
   the ends of components' stretches are clamped by it, in the blob's own
   units ([add_piece]) *)
let depth_tolerance = 1e-2

(* The stretch [t0, t1] of a component. As POV-Ray's elements do
   (intersect_sphere, _ellipsoid, _cylinder and _hemisphere in blob.cpp),
   an end marked [clamp0] or [clamp1] that lies before [depth_tolerance]
   is moved to 0, and the stretch is dropped when nothing is left: a
   stretch ending that near the origin counts nowhere; one starting in
   (0, depth_tolerance) counts from 0 on, its quartic summed there too,
   though the ray is outside the component, where the quartic rises
   again. *)
let[@inline] add_piece w t0 t1 clamp0 clamp1 s r2 a b c =
  let t0' = if clamp0 && t0 < depth_tolerance then 0. else t0
  and t1' = if clamp1 && t1 < depth_tolerance then 0. else t1 in
  if t1 > t0 && t1' > t0' then begin
    let t0 = t0' and t1 = t1' in
    if 7 * (w.n + 1) > Float.Array.length w.pieces then begin
      let p = Float.Array.make (2 * Float.Array.length w.pieces) 0. in
      Float.Array.blit w.pieces 0 p 0 (7 * w.n);
      w.pieces <- p
    end;
    (* s (1 - q / r^2)^2 = s / r^4 (q^2 - 2 r^2 q + r^4), q = a t^2 + b t + c *)
    let k = s /. (r2 *. r2) and o = 7 * w.n and p = w.pieces in
    Float.Array.unsafe_set p o t0;
    Float.Array.unsafe_set p (o + 1) t1;
    Float.Array.unsafe_set p (o + 2) (k *. ((c *. c) -. (2. *. r2 *. c) +. (r2 *. r2)));
    Float.Array.unsafe_set p (o + 3) (k *. ((2. *. b *. c) -. (2. *. r2 *. b)));
    Float.Array.unsafe_set p (o + 4) (k *. ((b *. b) +. (2. *. a *. c) -. (2. *. r2 *. a)));
    Float.Array.unsafe_set p (o + 5) (k *. 2. *. a *. b);
    Float.Array.unsafe_set p (o + 6) (k *. a *. a);
    w.n <- w.n + 1
  end

(* where a t^2 + b t + c < r2, clipped to (lo, hi): the stretch added.
   An end at [lo] or [hi] (a cylinder's end plane) is clamped (see
   [add_piece]); one where the ray meets the quadric when [rc] (a
   sphere's, a cylinder's side; not an end cap's, which POV-Ray leaves
   as they are) *)
let[@inline] within w s r2 a b c lo hi rc =
  if a > 1e-12 then begin
    let disc = (b *. b) -. (4. *. a *. (c -. r2)) in
    if disc > 0. then begin
      let sq = Float.sqrt disc in
      let r0 = (-.b -. sq) /. (2. *. a) and r1 = (-.b +. sq) /. (2. *. a) in
      (* [max lo r0, min hi r1], each end passed as a plain float (one
         chosen by an [if] would be boxed) *)
      if lo >= r0 then
        if hi <= r1 then add_piece w lo hi true true s r2 a b c else add_piece w lo r1 true rc s r2 a b c
      else if hi <= r1 then add_piece w r0 hi rc true s r2 a b c
      else add_piece w r0 r1 rc rc s r2 a b c
    end
  end
  else if c < r2 then add_piece w lo hi true true s r2 0. 0. c

(* The stretches of a sphere (centre [p]) along the ray [o + t n], where
   [dd] is [n . n] (1 in the blob's space, where [n] is the unit
   direction) *)
let[@inline] sphere_pieces w s r2 (p : Vec3.t) ox oy oz nx ny nz dd =
  let ex = ox -. p.x and ey = oy -. p.y and ez = oz -. p.z in
  within w s r2 dd (2. *. ((ex *. nx) +. (ey *. ny) +. (ez *. nz))) ((ex *. ex) +. (ey *. ey) +. (ez *. ez))
    neg_infinity infinity true

(* The same for a cylinder from [pa] to [pb] with round ends *)
let[@inline] cylinder_pieces w s r2 (pa : Vec3.t) (pb : Vec3.t) ox oy oz nx ny nz dd =
  let wx = pb.x -. pa.x and wy = pb.y -. pa.y and wz = pb.z -. pa.z in
  let len = Float.sqrt ((wx *. wx) +. (wy *. wy) +. (wz *. wz)) in
  let wx = wx /. len and wy = wy /. len and wz = wz /. len in
  let ex = ox -. pa.x and ey = oy -. pa.y and ez = oz -. pa.z in
  let h0 = (ex *. wx) +. (ey *. wy) +. (ez *. wz) and hw = (nx *. wx) +. (ny *. wy) +. (nz *. wz) in
  let en = (ex *. nx) +. (ey *. ny) +. (ez *. nz) and e2 = (ex *. ex) +. (ey *. ey) +. (ez *. ez) in
  let fx = ox -. pb.x and fy = oy -. pb.y and fz = oz -. pb.z in
  let fn = (fx *. nx) +. (fy *. ny) +. (fz *. nz) and f2 = (fx *. fx) +. (fy *. fy) +. (fz *. fz) in
  (* beside the segment (0 <= h <= len): the distance to the axis, the
     quadratic [ba t^2 + bb t + bc]; before its start (h < 0) and past its
     end (h > len): the distance to each end point *)
  let ba = dd -. (hw *. hw) and bb = 2. *. (en -. (h0 *. hw)) and bc = e2 -. (h0 *. h0) in
  if hw = 0. then begin
    if h0 < 0. then begin
      within w s r2 ba bb bc 1. 0. true;
      within w s r2 dd (2. *. en) e2 neg_infinity infinity false
    end
    else if h0 > len then begin
      within w s r2 ba bb bc 1. 0. true;
      within w s r2 dd (2. *. fn) f2 neg_infinity infinity false
    end
    else within w s r2 ba bb bc neg_infinity infinity true
  end
  else begin
    let t0 = -.h0 /. hw and t1 = (len -. h0) /. hw in
    if hw > 0. then begin
      within w s r2 ba bb bc t0 t1 true;
      within w s r2 dd (2. *. en) e2 neg_infinity t0 false;
      within w s r2 dd (2. *. fn) f2 t1 infinity false
    end
    else begin
      within w s r2 ba bb bc t1 t0 true;
      within w s r2 dd (2. *. en) e2 t0 infinity false;
      within w s r2 dd (2. *. fn) f2 neg_infinity t1 false
    end
  end

let collect b w (r : Ray.scratch) =
  let ox = r.ox and oy = r.oy and oz = r.oz and nx = w.dir.mx and ny = w.dir.my and nz = w.dir.mz in
  w.n <- 0;
  for ci = 0 to Array.length b.comps - 1 do
    let comp = Array.unsafe_get b.comps ci in
    let r = radius comp and s = strength comp in
    let r2 = r *. r in
    match comp with
    | Sphere { center = p; _ } -> sphere_pieces w s r2 p ox oy oz nx ny nz 1.
    | Cylinder { a = pa; b = pb; _ } -> cylinder_pieces w s r2 pa pb ox oy oz nx ny nz 1.
    | Placed { shape; _ } -> (
        (* the ray in the component's own space, the same parameter *)
        let m = b.inv and o = 12 * ci and lo = w.lo and ld = w.ld in
        to_local b ci ox oy oz lo;
        Vec3.set ld
          ((fget m o *. nx) +. (fget m (o + 1) *. ny) +. (fget m (o + 2) *. nz))
          ((fget m (o + 3) *. nx) +. (fget m (o + 4) *. ny) +. (fget m (o + 5) *. nz))
          ((fget m (o + 6) *. nx) +. (fget m (o + 7) *. ny) +. (fget m (o + 8) *. nz));
        let dd = (ld.mx *. ld.mx) +. (ld.my *. ld.my) +. (ld.mz *. ld.mz) in
        match shape with
        | Sphere { center = p; _ } -> sphere_pieces w s r2 p lo.mx lo.my lo.mz ld.mx ld.my ld.mz dd
        | Cylinder { a = pa; b = pb; _ } -> cylinder_pieces w s r2 pa pb lo.mx lo.my lo.mz ld.mx ld.my ld.mz dd
        | Placed _ -> ())
  done

(* Whether the quartic [sum] (constant first) surely has no root in [u,
   v]: its Bernstein coefficients on the stretch, which bound it there,
   are all of one sign by more than their rounding. Most stretches a ray
   crosses near a blob hold no surface; this saves them the root search
   (and decides nothing else: a stretch not ruled out is searched as
   before). *)
let[@inline] surely_rootless (p : Float.Array.t) u v =
  (* Taylor shift to u (Horner's scheme, repeated), then scale to [0, 1] *)
  let c0 = fget p 0 and c1 = fget p 1 and c2 = fget p 2 and c3 = fget p 3 and c4 = fget p 4 in
  let a0 = (((((c4 *. u) +. c3) *. u +. c2) *. u) +. c1) *. u +. c0 in
  let a1 = ((((4. *. c4 *. u) +. (3. *. c3)) *. u +. (2. *. c2)) *. u) +. c1 in
  let a2 = (((6. *. c4 *. u) +. (3. *. c3)) *. u) +. c2 in
  let a3 = (4. *. c4 *. u) +. c3 in
  let a4 = c4 in
  let hh = v -. u in
  let a1 = a1 *. hh and a2 = a2 *. hh *. hh and a3 = a3 *. hh *. hh *. hh and a4 = a4 *. hh *. hh *. hh *. hh in
  let b0 = a0 and b1 = a0 +. (a1 /. 4.) and b2 = a0 +. (a1 /. 2.) +. (a2 /. 6.)
  and b3 = a0 +. (0.75 *. a1) +. (a2 /. 2.) +. (a3 /. 4.) and b4 = a0 +. a1 +. a2 +. a3 +. a4 in
  let scale = Float.abs a0 +. Float.abs a1 +. Float.abs a2 +. Float.abs a3 +. Float.abs a4 in
  let eps = 1e-9 *. scale in
  (b0 > eps && b1 > eps && b2 > eps && b3 > eps && b4 > eps)
  || (b0 < -.eps && b1 < -.eps && b2 < -.eps && b3 < -.eps && b4 < -.eps)

let hit_s b (r : Ray.scratch) (world : Ray.scratch) tmin (h : Hit.t) =
  (* [+. 0.] keeps it unboxed: joined with a boxed argument, the choice
     would box [h.floor] *)
  let tmin = let t = tmin +. 0. in if h.floor > t then h.floor else t in
  (* POV-Ray's depth tolerance, a distance in the world: in units of the
     world ray's direction *)
  let wl = Float.sqrt ((world.dx *. world.dx) +. (world.dy *. world.dy) +. (world.dz *. world.dz)) in
  let tmin = fmax tmin (depth_tolerance /. wl) in
  let dl = Float.sqrt ((r.dx *. r.dx) +. (r.dy *. r.dy) +. (r.dz *. r.dz)) in
  let w = Scratch.get work_key in
  Vec3.set w.dir (r.dx /. dl) (r.dy /. dl) (r.dz /. dl);
  collect b w r;
  let n = w.n in
  if n = 0 then false
  else begin
    (* the stretches' ends, sorted *)
    if 2 * n > Float.Array.length w.ends then w.ends <- Float.Array.make (4 * n) 0.;
    let e = w.ends in
    for i = 0 to n - 1 do
      Float.Array.unsafe_set e (2 * i) (Float.Array.unsafe_get w.pieces (7 * i));
      Float.Array.unsafe_set e ((2 * i) + 1) (Float.Array.unsafe_get w.pieces ((7 * i) + 1))
    done;
    let m = 2 * n in
    Floats.sort_prefix e m;
    (* a stretch is searched whole, not cut at [h.t]: the root found must
       not depend on the order objects are tried in *)
    let lo_t = tmin *. dl and hi_t = h.t *. dl in
    let found = ref false and i = ref 0 in
    while (not !found) && !i < m - 1 && Float.Array.unsafe_get e !i < hi_t do
      let u = Float.Array.unsafe_get e !i and v = Float.Array.unsafe_get e (!i + 1) in
      let u = fmax u lo_t in
      if u < v then begin
        let mid = 0.5 *. (u +. v) in
        let sum = w.sum in
        Float.Array.fill sum 0 5 0.;
        for k = 0 to n - 1 do
          let o = 7 * k in
          if Float.Array.unsafe_get w.pieces o <= mid && mid <= Float.Array.unsafe_get w.pieces (o + 1) then
            for c = 0 to 4 do
              Float.Array.unsafe_set sum c (Float.Array.unsafe_get sum c +. Float.Array.unsafe_get w.pieces (o + 2 + c))
            done
        done;
        Float.Array.unsafe_set sum 0 (Float.Array.unsafe_get sum 0 -. b.threshold);
        if (not (surely_rootless sum u v)) && Poly.first_root_in w.roots sum 4 u v then begin
          (* the nearest root: nearer than [h.t], or none is *)
          let t = Poly.root w.roots /. dl in
          if t < h.t then begin
            h.t <- t;
            h.id <- 0.;
            found := true
          end
          else i := m
        end
      end;
      incr i
    done;
    !found
  end
