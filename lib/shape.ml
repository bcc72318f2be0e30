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
  if t > tmin && t < h.t then (
    h.t <- t;
    h.id <- id;
    true)
  else false

let hit_sphere (center : Vec3.t) radius (r : Ray.t) tmin (h : Hit.t) =
  let ox = r.origin.x -. center.x and oy = r.origin.y -. center.y and oz = r.origin.z -. center.z in
  let dx = r.dir.x and dy = r.dir.y and dz = r.dir.z in
  let a = (dx *. dx) +. (dy *. dy) +. (dz *. dz) in
  let hb = (ox *. dx) +. (oy *. dy) +. (oz *. dz) in
  let c = (ox *. ox) +. (oy *. oy) +. (oz *. oz) -. (radius *. radius) in
  let disc = (hb *. hb) -. (a *. c) in
  if disc < 0. then false
  else
    let sq = Float.sqrt disc in
    (* the numerically stable pair of roots *)
    let q = if hb > 0. then -.(hb +. sq) else -.hb +. sq in
    let t0 = q /. a and t1 = if q = 0. then 0. else c /. q in
    let lo = Float.min t0 t1 and hi = Float.max t0 t1 in
    accept h tmin lo 0. || accept h tmin hi 0.

(* Slab test along one axis, updating the entry (tn, face fn) and exit (tf,
   face ff) of the running interval; allocation-free. Returns false on a
   miss (ray parallel to the slab and outside it). *)
let[@inline] slab o d l u axis (a : Hit.t) =
  if d = 0. then o >= l && o <= u
  else begin
    let p = (l -. o) /. d and q = (u -. o) /. d in
    let near = if p < q then p else q and far = if p < q then q else p in
    let lo_face = 2. *. axis in
    if near > a.t then (
      a.t <- near;
      a.u <- (if p < q then lo_face else lo_face +. 1.));
    if far < a.v then (
      a.v <- far;
      a.id <- (if p < q then lo_face +. 1. else lo_face));
    true
  end

let hit_box (lo : Vec3.t) (hi : Vec3.t) (r : Ray.t) tmin (h : Hit.t) =
  (* the scratch holds entry distance and face (t, u), exit (v, id) *)
  let a = { Hit.t = neg_infinity; u = 0.; v = infinity; id = 0. } in
  slab r.origin.x r.dir.x lo.x hi.x 0. a
  && slab r.origin.y r.dir.y lo.y hi.y 1. a
  && slab r.origin.z r.dir.z lo.z hi.z 2. a
  && a.t <= a.v
  && (accept h tmin a.t a.u || accept h tmin a.v a.id)

let[@inline] cone_side oz dz length tmin (h : Hit.t) t =
  let z = oz +. (t *. dz) in
  z >= 0. && z <= length && accept h tmin t 0.

let[@inline] cone_cap ox oy oz dx dy dz tmin (h : Hit.t) zc rc id =
  let t = (zc -. oz) /. dz in
  let x = ox +. (t *. dx) and y = oy +. (t *. dy) in
  (x *. x) +. (y *. y) <= rc *. rc && accept h tmin t id

(* In the cone's frame (u, v, axis) the side is x^2 + y^2 = (r0 + k z)^2,
   0 <= z <= length; the caps are discs at z = 0 and z = length. *)
let hit_cone ~(base : Vec3.t) ~axis ~u ~v ~length ~r0 ~r1 ~open_ (r : Ray.t) tmin (h : Hit.t) =
  let o = Vec3.sub r.origin base in
  let ox = Vec3.dot o u and oy = Vec3.dot o v and oz = Vec3.dot o axis in
  let dx = Vec3.dot r.dir u and dy = Vec3.dot r.dir v and dz = Vec3.dot r.dir axis in
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

let hit_torus major minor (r : Ray.t) tmin (h : Hit.t) =
  let dl = Vec3.length r.dir in
  let dn = Vec3.scale (1. /. dl) r.dir in
  (* restart from the point of the ray nearest the centre: small, well
     scaled coefficients; the bounding sphere bounds the search *)
  let t0 = -.Vec3.dot r.origin dn in
  let q = Vec3.madd r.origin t0 dn in
  let rr = major +. minor in
  let q2 = Vec3.length2 q in
  if q2 > rr *. rr then false
  else
    let hh = Float.sqrt ((rr *. rr) -. q2) *. (1. +. 1e-9) in
    (* the upper end does not depend on [h.t], so that the root found never
       depends on the order objects are tried in *)
    let lo = Float.max (-.hh) ((tmin *. dl) -. t0) and hi = hh in
    if not (lo < hi) then false
    else
      let b = 2. *. Vec3.dot q dn in
      let c = q2 +. (major *. major) -. (minor *. minor) in
      let qa = (dn.x *. dn.x) +. (dn.z *. dn.z) in
      let qb = 2. *. ((q.x *. dn.x) +. (q.z *. dn.z)) in
      let qc = (q.x *. q.x) +. (q.z *. q.z) in
      let r4 = 4. *. major *. major in
      let s =
        Poly.first_quartic_root 1. (2. *. b)
          ((b *. b) +. (2. *. c) -. (r4 *. qa))
          ((2. *. b *. c) -. (r4 *. qb))
          ((c *. c) -. (r4 *. qc))
          lo hi
      in
      s < infinity && accept h tmin ((s +. t0) /. dl) 0.

let hit s (r : Ray.t) tmin (h : Hit.t) =
  match s with
  | Sphere { center; radius } -> hit_sphere center radius r tmin h
  | Plane { normal; offset } ->
      let dn = Vec3.dot r.dir normal in
      dn <> 0. && accept h tmin ((offset -. Vec3.dot r.origin normal) /. dn) 0.
  | Box { lo; hi } -> hit_box lo hi r tmin h
  | Cone { base; axis; u; v; length; r0; r1; open_ } ->
      hit_cone ~base ~axis ~u ~v ~length ~r0 ~r1 ~open_ r tmin h
  | Torus { major; minor } -> hit_torus major minor r tmin h
  | Disc { center; normal; radius; hole } ->
      let dn = Vec3.dot r.dir normal in
      dn <> 0.
      &&
      let t = Vec3.dot (Vec3.sub center r.origin) normal /. dn in
      t > tmin && t < h.t
      &&
      let d2 = Vec3.length2 (Vec3.sub (Ray.at r t) center) in
      d2 <= radius *. radius && d2 >= hole *. hole && accept h tmin t 0.
  | Triangle { a; b; c; _ } | Smooth_triangle { a; b; c; _ } ->
      Mesh.tri_hit a.x a.y a.z b.x b.y b.z c.x c.y c.z r tmin h
  | Mesh m -> Mesh.hit m r tmin h

let intersect s r tmin tmax =
  let h = Hit.create tmax in
  if hit s r tmin h then h.t else infinity

let normal s (p : Vec3.t) (h : Hit.t) =
  match s with
  | Sphere { center; radius } -> Vec3.scale (1. /. radius) (Vec3.sub p center)
  | Plane { normal; _ } | Disc { normal; _ } -> normal
  | Box _ -> (
      match int_of_float h.id with
      | 0 -> Vec3.neg Vec3.unit_x
      | 1 -> Vec3.unit_x
      | 2 -> Vec3.neg Vec3.unit_y
      | 3 -> Vec3.unit_y
      | 4 -> Vec3.neg Vec3.unit_z
      | _ -> Vec3.unit_z)
  | Cone { base; axis; u; v; length; r0; r1; _ } -> (
      match int_of_float h.id with
      | 1 -> Vec3.neg axis
      | 2 -> axis
      | _ ->
          let o = Vec3.sub p base in
          let x = Vec3.dot o u and y = Vec3.dot o v and z = Vec3.dot o axis in
          let k = (r1 -. r0) /. length in
          let rz = r0 +. (k *. z) in
          Vec3.normalize (Vec3.madd (Vec3.add (Vec3.scale x u) (Vec3.scale y v)) (-.k *. rz) axis))
  | Torus { major; _ } ->
      let rho = Float.sqrt ((p.x *. p.x) +. (p.z *. p.z)) in
      if rho = 0. then Vec3.unit_y
      else
        let k = major /. rho in
        Vec3.normalize (Vec3.make (p.x -. (k *. p.x)) p.y (p.z -. (k *. p.z)))
  | Triangle { n; _ } -> n
  | Smooth_triangle { na; nb; nc; _ } -> Mesh.smooth_normal na nb nc h.u h.v
  | Mesh m -> Mesh.normal m h

let inside s (p : Vec3.t) =
  match s with
  | Sphere { center; radius } -> Vec3.length2 (Vec3.sub p center) < radius *. radius
  | Plane { normal; offset } -> Vec3.dot normal p < offset
  | Box { lo; hi } -> p.x > lo.x && p.x < hi.x && p.y > lo.y && p.y < hi.y && p.z > lo.z && p.z < hi.z
  | Cone { base; axis; u; v; length; r0; r1; _ } ->
      let o = Vec3.sub p base in
      let z = Vec3.dot o axis in
      z > 0. && z < length
      &&
      let x = Vec3.dot o u and y = Vec3.dot o v in
      let rz = r0 +. ((r1 -. r0) *. z /. length) in
      (x *. x) +. (y *. y) < rz *. rz
  | Torus { major; minor } ->
      let rho = Float.sqrt ((p.x *. p.x) +. (p.z *. p.z)) -. major in
      (rho *. rho) +. (p.y *. p.y) < minor *. minor
  | Disc { center; normal; _ } -> Vec3.dot (Vec3.sub p center) normal < 0.
  | Triangle _ | Smooth_triangle _ -> false
  | Mesh m -> Mesh.inside m p

(* Bounds of a disc of radius r around c with unit normal n. *)
let disc_bounds (c : Vec3.t) (n : Vec3.t) r =
  let e a = r *. Float.sqrt (Float.max 0. (1. -. (a *. a))) in
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
