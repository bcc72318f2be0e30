type t =
  | Sphere of { center : Vec3.t; radius : float }
  | Plane of { normal : Vec3.t; offset : float }
  | Box of { lo : Vec3.t; hi : Vec3.t }
  | Cone of {
      base : Vec3.t;
      axis : Vec3.t;
      u : Vec3.t;
      v : Vec3.t;
      length : float;
      r0 : float;
      r1 : float;
      open_ : bool;
    }
  | Torus of { major : float; minor : float }
  | Disc of { center : Vec3.t; normal : Vec3.t; radius : float; hole : float }
  | Triangle of { a : Vec3.t; b : Vec3.t; c : Vec3.t; n : Vec3.t }
  | Smooth_triangle of { a : Vec3.t; b : Vec3.t; c : Vec3.t; na : Vec3.t; nb : Vec3.t; nc : Vec3.t }
  | Mesh of Mesh.t
  | Algebraic of Algebraic.t
  | Text of Text.t
  | Blob of Blob.t
  | Prism of Prism.t
  | Lathe of Lathe.t
  | Sor of Sor.t
  | Superellipsoid of Superellipsoid.t
  | Julia of Julia.t
  | Polygon of Polygon.t  (** POV-Ray's [polygon] *)
  | Height_field of Height_field.t  (** POV-Ray's [height_field] *)
  | Isosurface of Isosurface.t  (** POV-Ray's [isosurface] *)

let sphere center radius = Sphere { center; radius }
let plane n d = Plane { normal = Vec3.normalize n; offset = d }
let box a b = Box { lo = Vec3.min a b; hi = Vec3.max a b }

(* Some unit vector perpendicular to the unit vector w. *)
let perp (w : Vec3.t) =
  let a = if Float.abs w.x < 0.6 then Vec3.unit_x else if Float.abs w.y < 0.6 then Vec3.unit_y else Vec3.unit_z in
  Vec3.normalize (Vec3.cross w a)

let cone ?(open_ = false) b rb t rt =
  let d = Vec3.sub t b in
  let axis = Vec3.normalize d in
  let u = perp axis in
  Cone { base = b; axis; u; v = Vec3.cross axis u; length = Vec3.length d; r0 = rb; r1 = rt; open_ }

let cylinder ?open_ b t r = cone ?open_ b r t r
let torus major minor = Torus { major; minor }
let disc ?(hole = 0.) center n radius = Disc { center; normal = Vec3.normalize n; radius; hole }
let triangle a b c = Triangle { a; b; c; n = Vec3.normalize (Vec3.cross (Vec3.sub b a) (Vec3.sub c a)) }

let smooth_triangle a na b nb c nc =
  Smooth_triangle { a; b; c; na = Vec3.normalize na; nb = Vec3.normalize nb; nc = Vec3.normalize nc }

let[@inline] accept (h : Hit.t) tmin t id =
  if t > tmin && t > h.floor && t < h.t then (
    h.t <- t;
    h.id <- id;
    true)
  else false

(* POV-Ray 3.7's sphere (spheres.cpp's Intersect): along a unit
   direction, the distance to the point nearest the centre less and plus
   the half chord; no crossing when the ray starts outside and heads
   away (that distance under 1e-10) or when the squared half chord is
   1e-10 or less. A direction that is not of unit length (a sphere under
   a transformation that is not a similarity) is made unit first and
   the distances scaled back, as POV-Ray does for an ellipsoid. The
   nearest crossing in (lo, hi), or infinity. *)
let[@inline] sphere_nearest cx cy cz radius (r : Ray.scratch) lo hi =
  let dx = r.dx and dy = r.dy and dz = r.dz in
  let l2 = (dx *. dx) +. (dy *. dy) +. (dz *. dz) in
  let unit = Float.abs (l2 -. 1.) < 1e-12 in
  let len = if unit then 1. else Float.sqrt l2 in
  let k = 1. /. len in
  let dx = if unit then dx else dx *. k and dy = if unit then dy else dy *. k and dz = if unit then dz else dz *. k in
  let ox = cx -. r.ox and oy = cy -. r.oy and oz = cz -. r.oz in
  let oc2 = (ox *. ox) +. (oy *. oy) +. (oz *. oz) in
  let tca = (ox *. dx) +. (oy *. dy) +. (oz *. dz) in
  let r2 = radius *. radius in
  let hc2 = r2 -. oc2 +. (tca *. tca) in
  if (oc2 >= r2 && tca < 1e-10) || not (hc2 > 1e-10) then infinity
  else begin
    let hc = Float.sqrt hc2 in
    let t1 = (tca -. hc) /. len and t2 = (tca +. hc) /. len in
    if t1 > lo && t1 < hi then t1 else if t2 > lo && t2 < hi then t2 else infinity
  end

let[@inline] hit_sphere (center : Vec3.t) radius (r : Ray.scratch) tmin (h : Hit.t) =
  let lo = if h.floor > tmin then h.floor else tmin in
  let t = sphere_nearest center.x center.y center.z radius r lo h.t in
  t < infinity && accept h tmin t 0.

(* Entry and exit of the ray in one slab (a parallel ray outside it gets an
   empty interval), and the face crossed at each: 2 axis for the low
   plane, 2 axis + 1 for the high one. *)
let[@inline] slab_near o d l u =
  if d = 0. then if o >= l && o <= u then neg_infinity else infinity
  else
    let p = (l -. o) /. d and q = (u -. o) /. d in
    if p < q then p else q

let[@inline] slab_far o d l u =
  if d = 0. then if o >= l && o <= u then infinity else neg_infinity
  else
    let p = (l -. o) /. d and q = (u -. o) /. d in
    if p < q then q else p

let[@inline] near_face o d l u axis = if (l -. o) /. d < (u -. o) /. d then 2. *. axis else (2. *. axis) +. 1.
let[@inline] far_face o d l u axis = if (l -. o) /. d < (u -. o) /. d then (2. *. axis) +. 1. else 2. *. axis

let hit_box (lo : Vec3.t) (hi : Vec3.t) (r : Ray.scratch) tmin (h : Hit.t) =
  let nx = slab_near r.ox r.dx lo.x hi.x and fx = slab_far r.ox r.dx lo.x hi.x in
  let ny = slab_near r.oy r.dy lo.y hi.y and fy = slab_far r.oy r.dy lo.y hi.y in
  let nz = slab_near r.oz r.dz lo.z hi.z and fz = slab_far r.oz r.dz lo.z hi.z in
  (* entry: the last plane entered (first axis on ties); exit: the first left *)
  let n1 = if ny > nx then ny else nx and f1 = if fy < fx then fy else fx in
  let tn = if nz > n1 then nz else n1 and tf = if fz < f1 then fz else f1 in
  tn <= tf
  && (let fn =
        if nz > n1 then near_face r.oz r.dz lo.z hi.z 2.
        else if ny > nx then near_face r.oy r.dy lo.y hi.y 1.
        else if nx > neg_infinity then near_face r.ox r.dx lo.x hi.x 0.
        else 0.
      in
      accept h tmin tn fn)
  ||
  let ff =
    if fz < f1 then far_face r.oz r.dz lo.z hi.z 2.
    else if fy < fx then far_face r.oy r.dy lo.y hi.y 1.
    else if fx < infinity then far_face r.ox r.dx lo.x hi.x 0.
    else 0.
  in
  tn <= tf && accept h tmin tf ff

let[@inline] cone_side oz dz length tmin (h : Hit.t) t =
  let z = oz +. (t *. dz) in
  z >= 0. && z <= length && accept h tmin t 0.

let[@inline] cone_cap ox oy oz dx dy dz tmin (h : Hit.t) zc rc id =
  let t = (zc -. oz) /. dz in
  let x = ox +. (t *. dx) and y = oy +. (t *. dy) in
  (x *. x) +. (y *. y) <= rc *. rc && accept h tmin t id

(* In the cone's frame (u, v, axis) the side is x^2 + y^2 = (r0 + k z)^2,
   0 <= z <= length; the caps are discs at z = 0 and z = length. *)
let hit_cone ~(base : Vec3.t) ~(axis : Vec3.t) ~(u : Vec3.t) ~(v : Vec3.t) ~length ~r0 ~r1 ~open_
    (r : Ray.scratch) tmin (h : Hit.t) =
  let px = r.ox -. base.x and py = r.oy -. base.y and pz = r.oz -. base.z in
  let ox = (px *. u.x) +. (py *. u.y) +. (pz *. u.z)
  and oy = (px *. v.x) +. (py *. v.y) +. (pz *. v.z)
  and oz = (px *. axis.x) +. (py *. axis.y) +. (pz *. axis.z) in
  let dx = (r.dx *. u.x) +. (r.dy *. u.y) +. (r.dz *. u.z)
  and dy = (r.dx *. v.x) +. (r.dy *. v.y) +. (r.dz *. v.z)
  and dz = (r.dx *. axis.x) +. (r.dy *. axis.y) +. (r.dz *. axis.z) in
  let k = (r1 -. r0) /. length in
  let rz0 = r0 +. (k *. oz) in
  let a = (dx *. dx) +. (dy *. dy) -. (k *. k *. dz *. dz) in
  let hb = (ox *. dx) +. (oy *. dy) -. (rz0 *. k *. dz) in
  let c = (ox *. ox) +. (oy *. oy) -. (rz0 *. rz0) in
  let side =
    if Float.abs a > 1e-12 *. ((dx *. dx) +. (dy *. dy) +. (dz *. dz)) then begin
      let disc = (hb *. hb) -. (a *. c) in
      disc >= 0.
      &&
      let sq = Float.sqrt disc in
      let q = if hb > 0. then -.(hb +. sq) else -.hb +. sq in
      let t0 = q /. a and t1 = if q = 0. then 0. else c /. q in
      let lo = if t0 < t1 then t0 else t1 and hi = if t0 < t1 then t1 else t0 in
      let f0 = cone_side oz dz length tmin h lo in
      let f1 = cone_side oz dz length tmin h hi in
      f0 || f1
    end
    else hb <> 0. && cone_side oz dz length tmin h (-.c /. (2. *. hb))
  in
  if (not open_) && dz <> 0. then
    let c0 = cone_cap ox oy oz dx dy dz tmin h 0. r0 1. in
    let c1 = cone_cap ox oy oz dx dy dz tmin h length r1 2. in
    side || c0 || c1
  else side

let hit_torus major minor (r : Ray.scratch) tmin (h : Hit.t) =
  (* the search starts past the floor: the first root after it *)
  (* [+. 0.] keeps it unboxed: joined with a boxed argument, the choice
     would box [h.floor] *)
  let tmin = let t = tmin +. 0. in if h.floor > t then h.floor else t in
  let dl = Float.sqrt ((r.dx *. r.dx) +. (r.dy *. r.dy) +. (r.dz *. r.dz)) in
  let nx = r.dx /. dl and ny = r.dy /. dl and nz = r.dz /. dl in
  (* restart from the point of the ray nearest the centre: small, well
     scaled coefficients; the bounding sphere bounds the search *)
  let t0 = -.((r.ox *. nx) +. (r.oy *. ny) +. (r.oz *. nz)) in
  let qx = r.ox +. (t0 *. nx) and qy = r.oy +. (t0 *. ny) and qz = r.oz +. (t0 *. nz) in
  let rr = major +. minor in
  let q2 = (qx *. qx) +. (qy *. qy) +. (qz *. qz) in
  if q2 > rr *. rr then false
  else
    let hh = Float.sqrt ((rr *. rr) -. q2) *. (1. +. 1e-9) in
    (* the upper end does not depend on [h.t], so that the root found never
       depends on the order objects are tried in *)
    let lo = (tmin *. dl) -. t0 in
    let lo = if lo > -.hh then lo else -.hh and hi = hh in
    if not (lo < hi) then false
    else
      let b = 2. *. ((qx *. nx) +. (qy *. ny) +. (qz *. nz)) in
      let c = q2 +. (major *. major) -. (minor *. minor) in
      let qa = (nx *. nx) +. (nz *. nz) in
      let qb = 2. *. ((qx *. nx) +. (qz *. nz)) in
      let qc = (qx *. qx) +. (qz *. qz) in
      let r4 = 4. *. major *. major in
      let s =
        Poly.first_quartic_root 1. (2. *. b)
          ((b *. b) +. (2. *. c) -. (r4 *. qa))
          ((2. *. b *. c) -. (r4 *. qb))
          ((c *. c) -. (r4 *. qc))
          lo hi
      in
      s < infinity && accept h tmin ((s +. t0) /. dl) 0.

let hit_s s (r : Ray.scratch) tmin (h : Hit.t) =
  match s with
  | Sphere { center; radius } -> hit_sphere center radius r tmin h
  | Plane { normal = n; offset } ->
      let dn = (r.dx *. n.x) +. (r.dy *. n.y) +. (r.dz *. n.z) in
      dn <> 0. && accept h tmin ((offset -. ((r.ox *. n.x) +. (r.oy *. n.y) +. (r.oz *. n.z))) /. dn) 0.
  | Box { lo; hi } -> hit_box lo hi r tmin h
  | Cone { base; axis; u; v; length; r0; r1; open_ } ->
      hit_cone ~base ~axis ~u ~v ~length ~r0 ~r1 ~open_ r tmin h
  | Torus { major; minor } -> hit_torus major minor r tmin h
  | Disc { center = c; normal = n; radius; hole } ->
      let dn = (r.dx *. n.x) +. (r.dy *. n.y) +. (r.dz *. n.z) in
      dn <> 0.
      &&
      let t = (((c.x -. r.ox) *. n.x) +. ((c.y -. r.oy) *. n.y) +. ((c.z -. r.oz) *. n.z)) /. dn in
      t > tmin && t < h.t
      &&
      let px = r.ox +. (t *. r.dx) -. c.x and py = r.oy +. (t *. r.dy) -. c.y
      and pz = r.oz +. (t *. r.dz) -. c.z in
      let d2 = (px *. px) +. (py *. py) +. (pz *. pz) in
      d2 <= radius *. radius && d2 >= hole *. hole && accept h tmin t 0.
  | Triangle { a; b; c; _ } | Smooth_triangle { a; b; c; _ } ->
      Mesh.tri_hit a.x a.y a.z b.x b.y b.z c.x c.y c.z r tmin h
      && (h.id <- 0.;
          true)
  | Mesh m -> Mesh.hit_s m r tmin h
  | Algebraic a -> Algebraic.hit_s a r tmin h
  | Text t -> Text.hit_s t r tmin h
  | Blob b -> Blob.hit_s b r r tmin h
  | Prism p -> Prism.hit_s p r tmin h
  | Lathe l -> Lathe.hit_s l r tmin h
  | Sor s -> Sor.hit_s s r tmin h
  | Superellipsoid se -> Superellipsoid.hit_s se r tmin h
  | Julia j -> Julia.hit_s j r tmin h
  | Polygon pg -> Polygon.hit_s pg r tmin h
  | Height_field f -> Height_field.hit_s f r tmin h
  | Isosurface i -> Isosurface.hit_s i r tmin h

let hit s r tmin h = hit_s s (Ray.of_ray r) tmin h

let intersect s r tmin tmax =
  let h = Hit.create tmax in
  if hit s r tmin h then h.t else infinity

(* a box's faces: made once *)
let minus_x = Vec3.neg Vec3.unit_x
let minus_y = Vec3.neg Vec3.unit_y
let minus_z = Vec3.neg Vec3.unit_z

(* The outward unit normal at [p], into [out]; [p] is read before [out]
   is written, so they may be the same vector *)
let normal_into s (p : Vec3.m) (h : Hit.t) (out : Vec3.m) =
  match s with
  | Sphere { center; radius } ->
      let k = 1. /. radius in
      Vec3.set out (k *. (p.mx -. center.x)) (k *. (p.my -. center.y)) (k *. (p.mz -. center.z))
  | Plane { normal; _ } | Disc { normal; _ } | Triangle { n = normal; _ } -> Vec3.load out normal
  | Polygon pg -> Vec3.load out (Polygon.normal pg)
  | Height_field f -> Height_field.normal_into f p h out
  | Box _ -> (
      match int_of_float h.id with
      | 0 -> Vec3.load out minus_x
      | 1 -> Vec3.load out Vec3.unit_x
      | 2 -> Vec3.load out minus_y
      | 3 -> Vec3.load out Vec3.unit_y
      | 4 -> Vec3.load out minus_z
      | _ -> Vec3.load out Vec3.unit_z)
  | Cone { base; axis; u; v; length; r0; r1; _ } -> (
      match int_of_float h.id with
      | 1 -> Vec3.set out (-.axis.x) (-.axis.y) (-.axis.z)
      | 2 -> Vec3.load out axis
      | _ ->
          let ox = p.mx -. base.x and oy = p.my -. base.y and oz = p.mz -. base.z in
          let x = (ox *. u.x) +. (oy *. u.y) +. (oz *. u.z)
          and y = (ox *. v.x) +. (oy *. v.y) +. (oz *. v.z)
          and z = (ox *. axis.x) +. (oy *. axis.y) +. (oz *. axis.z) in
          let k = (r1 -. r0) /. length in
          let rz = r0 +. (k *. z) in
          let c = -.k *. rz in
          Vec3.set out
            ((x *. u.x) +. (y *. v.x) +. (c *. axis.x))
            ((x *. u.y) +. (y *. v.y) +. (c *. axis.y))
            ((x *. u.z) +. (y *. v.z) +. (c *. axis.z));
          Vec3.normalize_m out)
  | Torus { major; _ } ->
      let px = p.mx and py = p.my and pz = p.mz in
      let rho = Float.sqrt ((px *. px) +. (pz *. pz)) in
      if rho = 0. then Vec3.load out Vec3.unit_y
      else begin
        let k = major /. rho in
        Vec3.set out (px -. (k *. px)) py (pz -. (k *. pz));
        Vec3.normalize_m out
      end
  | Smooth_triangle { na; nb; nc; _ } -> Mesh.smooth_normal_into na nb nc h out
  | Mesh m -> Mesh.normal_into m h out
  | Algebraic a ->
      Algebraic.gradient_into a p.mx p.my p.mz out;
      (* POV-Ray's normal where the gradient vanishes *)
      if out.mx = 0. && out.my = 0. && out.mz = 0. then Vec3.load out Vec3.unit_x else Vec3.normalize_m out
  | Text t -> Text.normal_into t h out
  | Blob b -> Blob.normal_into b p out
  | Prism pr -> Prism.normal_into pr p h out
  | Lathe l -> Lathe.normal_into l p h out
  | Sor s -> Sor.normal_into s p h out
  | Superellipsoid se -> Superellipsoid.normal_into se p out
  | Julia j -> Julia.normal_into j p out
  | Isosurface i -> Isosurface.normal_into i p h out

let normal s (p : Vec3.t) h =
  let pm = Vec3.m () in
  Vec3.load pm p;
  normal_into s pm h pm;
  Vec3.of_m pm

(* POV-Ray 3.7's uv coordinates of a point of the surface (measured
   against POV-Ray: its colours at gradient-mapped uv) *)
let uv_into s (p : Vec3.m) (h : Hit.t) (out : Vec3.m) =
  let two_pi = 2. *. Float.pi in
  let turn a = (if a < 0. then a +. two_pi else a) /. two_pi in
  match s with
  | Sphere { center; _ } ->
      let x = p.mx -. center.x and y = p.my -. center.y and z = p.mz -. center.z in
      let l = Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) in
      if l = 0. then Vec3.set out 0. 0. 0.
      else
        (* u: the longitude from +x towards +z; v: the latitude, 0 at -y *)
        let v = 0.5 +. (Float.asin (Floats.fmax (-1.) (Floats.fmin 1. (y /. l))) /. Float.pi) in
        let u = if (x *. x) +. (z *. z) > 1e-20 *. l *. l then turn (Float.atan2 z x) else 0. in
        Vec3.set out u v 0.
  | Box { lo; hi } ->
      (* the faces unfolded into a cross: -x, -z, +x, +z around the
         middle band v in [1/3, 2/3]; -y below and +y above the +z face *)
      let nx = if hi.x > lo.x then (p.mx -. lo.x) /. (hi.x -. lo.x) else p.mx -. lo.x
      and ny = if hi.y > lo.y then (p.my -. lo.y) /. (hi.y -. lo.y) else p.my -. lo.y
      and nz = if hi.z > lo.z then (p.mz -. lo.z) /. (hi.z -. lo.z) else p.mz -. lo.z in
      let third = 1. /. 3. in
      (match int_of_float h.id with
      | 0 -> Vec3.set out (nz /. 4.) (third +. (ny /. 3.)) 0.
      | 1 -> Vec3.set out (0.75 -. (nz /. 4.)) (third +. (ny /. 3.)) 0.
      | 2 -> Vec3.set out (0.25 +. (nx /. 4.)) (nz /. 3.) 0.
      | 3 -> Vec3.set out (0.25 +. (nx /. 4.)) (1. -. (nz /. 3.)) 0.
      | 4 -> Vec3.set out (1. -. (nx /. 4.)) (third +. (ny /. 3.)) 0.
      | _ -> Vec3.set out (0.25 +. (nx /. 4.)) (third +. (ny /. 3.)) 0.)
  | Torus { major; _ } ->
      (* u around the axis from -x towards +z; v around the tube from
         the inner equator, down through the outer one *)
      let x = p.mx and y = p.my and z = p.mz in
      let rho = Float.sqrt ((x *. x) +. (z *. z)) in
      Vec3.set out (turn (Float.atan2 z (-.x))) (turn (Float.atan2 (-.y) (major -. rho))) 0.
  | Mesh m -> Mesh.uv_into m h out
  | _ -> Vec3.set out 0. 0. 0.

let[@inline] inside_xyz s x y z =
  match s with
  | Sphere { center = c; radius } ->
      let px = x -. c.x and py = y -. c.y and pz = z -. c.z in
      (px *. px) +. (py *. py) +. (pz *. pz) < radius *. radius
  | Plane { normal = n; offset } -> (n.x *. x) +. (n.y *. y) +. (n.z *. z) < offset
  | Box { lo; hi } -> x > lo.x && x < hi.x && y > lo.y && y < hi.y && z > lo.z && z < hi.z
  | Cone { base; axis; u; v; length; r0; r1; _ } ->
      let px = x -. base.x and py = y -. base.y and pz = z -. base.z in
      let oz = (px *. axis.x) +. (py *. axis.y) +. (pz *. axis.z) in
      oz > 0. && oz < length
      &&
      let ox = (px *. u.x) +. (py *. u.y) +. (pz *. u.z) and oy = (px *. v.x) +. (py *. v.y) +. (pz *. v.z) in
      let rz = r0 +. ((r1 -. r0) *. oz /. length) in
      (ox *. ox) +. (oy *. oy) < rz *. rz
  | Torus { major; minor } ->
      let rho = Float.sqrt ((x *. x) +. (z *. z)) -. major in
      (rho *. rho) +. (y *. y) < minor *. minor
  | Disc { center = c; normal = n; _ } -> ((x -. c.x) *. n.x) +. ((y -. c.y) *. n.y) +. ((z -. c.z) *. n.z) < 0.
  | Triangle _ | Smooth_triangle _ | Polygon _ -> false
  | Mesh m -> Mesh.inside_xyz m x y z
  | Height_field f -> Height_field.inside f x y z
  | Algebraic a -> Algebraic.inside a x y z
  | Text t -> Text.inside t x y z
  | Blob b -> Blob.inside b x y z
  | Prism p -> Prism.inside p x y z
  | Lathe l -> Lathe.inside l x y z
  | Sor s -> Sor.inside s x y z
  | Superellipsoid se -> Superellipsoid.inside se x y z
  | Julia j -> Julia.inside j x y z
  | Isosurface i -> Isosurface.inside i x y z

let inside_s s (p : Ray.scratch) = inside_xyz s p.ox p.oy p.oz
let inside s (p : Vec3.t) = inside_xyz s p.x p.y p.z

(* Bounds of a disc of radius r around c with unit normal n. *)
let disc_bounds (c : Vec3.t) (n : Vec3.t) r =
  let e a = r *. Float.sqrt (Floats.fmax 0. (1. -. (a *. a))) in
  let d = Vec3.make (e n.x) (e n.y) (e n.z) in
  (Vec3.sub c d, Vec3.add c d)

let bounds = function
  | Sphere { center; radius } ->
      let r = Vec3.make radius radius radius in
      Some (Vec3.sub center r, Vec3.add center r)
  | Plane _ -> None
  | Box { lo; hi } -> Some (lo, hi)
  | Cone { base; axis; length; r0; r1; _ } ->
      let l0, h0 = disc_bounds base axis r0 and l1, h1 = disc_bounds (Vec3.madd base length axis) axis r1 in
      Some (Vec3.min l0 l1, Vec3.max h0 h1)
  | Torus { major; minor } ->
      let e = major +. minor in
      Some (Vec3.make (-.e) (-.minor) (-.e), Vec3.make e minor e)
  | Disc { center; normal; radius; _ } -> Some (disc_bounds center normal radius)
  | Triangle { a; b; c; _ } | Smooth_triangle { a; b; c; _ } ->
      Some (Vec3.min a (Vec3.min b c), Vec3.max a (Vec3.max b c))
  | Mesh m -> Some (Mesh.bounds m)
  | Algebraic _ -> None
  | Text t -> Some (Text.bounds t)
  | Blob b -> Blob.bounds b
  | Prism p -> Some (Prism.bounds p)
  | Lathe l -> Some (Lathe.bounds l)
  | Sor s -> Some (Sor.bounds s)
  | Superellipsoid _ -> Some Superellipsoid.bounds
  | Julia j -> Some (Julia.bounds j)
  | Polygon pg -> Some (Polygon.bounds pg)
  | Height_field f -> Some (Height_field.bounds f)
  | Isosurface i -> Some (Isosurface.bounds i)
