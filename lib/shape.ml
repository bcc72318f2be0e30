type t =
  | Sphere of { center : Vec3.t; radius : float }
  | Plane of { normal : Vec3.t; offset : float }

let sphere center radius = Sphere { center; radius }
let plane n d = Plane { normal = Vec3.normalize n; offset = d }

let intersect s (r : Ray.t) tmin tmax =
  match s with
  | Sphere { center; radius } ->
      let oc = Vec3.sub r.origin center in
      let a = Vec3.dot r.dir r.dir in
      let hb = Vec3.dot oc r.dir in
      let c = Vec3.dot oc oc -. (radius *. radius) in
      let disc = (hb *. hb) -. (a *. c) in
      if disc < 0. then infinity
      else
        let sq = Float.sqrt disc in
        let t0 = (-.hb -. sq) /. a in
        if t0 > tmin && t0 < tmax then t0
        else
          let t1 = (-.hb +. sq) /. a in
          if t1 > tmin && t1 < tmax then t1 else infinity
  | Plane { normal; offset } ->
      let dn = Vec3.dot r.dir normal in
      if dn = 0. then infinity
      else
        let t = (offset -. Vec3.dot r.origin normal) /. dn in
        if t > tmin && t < tmax then t else infinity

let normal s p =
  match s with
  | Sphere { center; radius } -> Vec3.scale (1. /. radius) (Vec3.sub p center)
  | Plane { normal; _ } -> normal

let inside s p =
  match s with
  | Sphere { center; radius } -> Vec3.length2 (Vec3.sub p center) < radius *. radius
  | Plane { normal; offset } -> Vec3.dot normal p < offset

let bounds = function
  | Sphere { center; radius } ->
      let r = Vec3.make radius radius radius in
      Some (Vec3.sub center r, Vec3.add center r)
  | Plane _ -> None
