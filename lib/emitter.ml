(* if-based min/max: Float.min/max order NaN and -0 through a C call *)
let[@inline] fmax (a : float) b = if a >= b then a else b

type t =
  | Delta of Light.t
  | Area of { light : Light.t; area : Light.area }
  | Sphere of { obj : Object.t; center : Vec3.t; radius : float }

let emission (o : Object.t) p =
  match o.texture with
  | [] -> Color.black
  | (layer : Texture.layer) :: _ ->
      let pc = Pigment.eval layer.pigment p in
      let alpha = fmax 0. (1. -. pc.filter -. pc.transmit) in
      Color.scale alpha (Color.mul pc.c layer.finish.emission)

let emission_into (o : Object.t) (p : Vec3.m) (pc : Pigment.out) (out : Color.acc) =
  match o.texture with
  | [] -> Color.acc_set out 0. 0. 0.
  | (layer : Texture.layer) :: _ ->
      Pigment.into layer.pigment p pc;
      let alpha = fmax 0. (1. -. pc.filter -. pc.transmit) and e = layer.finish.emission in
      Color.acc_set out (alpha *. (pc.r *. e.r)) (alpha *. (pc.g *. e.g)) (alpha *. (pc.b *. e.b))

let emissive (o : Object.t) =
  match o.texture with
  | [] -> false
  | layer :: _ -> not (Color.is_black layer.finish.emission)

(* A sphere under a similarity transform stays a sphere. *)
let world_sphere (o : Object.t) =
  match o.geom with
  | Object.Prim (Shape.Sphere { center; radius }) ->
      let x = Transform.vector o.xform Vec3.unit_x
      and y = Transform.vector o.xform Vec3.unit_y
      and z = Transform.vector o.xform Vec3.unit_z in
      let lx = Vec3.length x in
      let near a b = Float.abs (a -. b) <= 1e-9 *. fmax 1. lx in
      if near (Vec3.length y) lx && near (Vec3.length z) lx
         && near (Vec3.dot x y) 0. && near (Vec3.dot y z) 0. && near (Vec3.dot x z) 0.
      then Some (Transform.point o.xform center, radius *. lx)
      else None
  | _ -> None

let of_scene (s : Scene.t) =
  let lights =
    Array.to_list
      (Array.map
         (fun (l : Light.t) ->
           match l.area with Some area -> Area { light = l; area } | None -> Delta l)
         (Scene.all_lights s))
  in
  let objs =
    Array.to_list s.objects
    |> List.filter_map (fun o ->
           if not (emissive o) then None
           else
             Option.map (fun (center, radius) -> Sphere { obj = o; center; radius }) (world_sphere o))
  in
  Array.of_list (lights @ objs)

type sample = { wi : Vec3.t; dist : float; value : Color.t; pdf : float }

let two_pi = 2. *. Float.pi

(* In place: [sample] into the caller's records. *)
type nums = { mutable dist : float; mutable pdf : float }
type sampled = {
  wi : Vec3.m;
  value : Color.acc;
  n : nums;
  pos : Vec3.m;  (** where the light is *)
  ld : Light.dir;  (** scratch *)
}

let sampled () =
  { wi = Vec3.m (); value = Color.acc 0.; n = { dist = 0.; pdf = 0. }; pos = Vec3.m (); ld = Light.dir () }

(* [point_light l pos p] into [out], [pos] in [out.pos]: the light's
   direction and attenuation as if it stood there *)
let point_light_into (l : Light.t) (p : Vec3.m) out =
  let pos = out.pos and ld = out.ld in
  Light.direction_at l pos.mx pos.my pos.mz p ld;
  Vec3.set out.wi ld.lx ld.ly ld.lz;
  out.n.dist <- ld.dist;
  let att = Light.attenuation_at l pos.mx pos.my pos.mz p in
  (not (att <= 0. || ld.dist <= 0.))
  && begin
       let k = Float.pi *. att in
       Color.acc_set out.value (k *. l.color.r) (k *. l.color.g) (k *. l.color.b);
       out.n.pdf <- 0.;
       true
     end

(* the value form of [point_light_into] *)
let point_light l (pos : Vec3.t) p =
  let out = sampled () and pm = Vec3.m () in
  Vec3.load pm p;
  Vec3.load out.pos pos;
  if point_light_into l pm out then
    Some { wi = Vec3.of_m out.wi; dist = out.n.dist; value = Color.of_acc out.value; pdf = out.n.pdf }
  else None

let cos_max r d = Float.sqrt (fmax 0. (1. -. (r *. r /. (d *. d))))

let sample e p u v =
  match e with
  | Delta l -> point_light l l.position p
  | Area { light; area } -> point_light light (Light.position_at light area p (u -. 0.5) (v -. 0.5)) p
  | Sphere { center; radius; _ } ->
      let to_c = Vec3.sub center p in
      let d = Vec3.length to_c in
      if d > radius then
        (* uniform in the subtended cone *)
        let cm = cos_max radius d in
        let c = 1. -. (u *. (1. -. cm)) in
        let wi =
          let s = Float.sqrt (fmax 0. (1. -. (c *. c))) and phi = two_pi *. v in
          let t, b = Bsdf.basis (Vec3.scale (1. /. d) to_c) in
          Vec3.add
            (Vec3.add (Vec3.scale (s *. Float.cos phi) t) (Vec3.scale (s *. Float.sin phi) b))
            (Vec3.scale (c /. d) to_c)
        in
        Some { wi; dist = d +. radius; value = Color.black; pdf = 1. /. (two_pi *. (1. -. cm)) }
      else
        (* inside: uniform by area *)
        let z = 1. -. (2. *. u) in
        let s = Float.sqrt (fmax 0. (1. -. (z *. z))) and phi = two_pi *. v in
        let nq = Vec3.make (s *. Float.cos phi) (s *. Float.sin phi) z in
        let q = Vec3.madd center radius nq in
        let w = Vec3.sub q p in
        let dist = Vec3.length w in
        let wi = Vec3.scale (1. /. dist) w in
        let c = Float.abs (Vec3.dot wi nq) in
        if c <= 0. then None
        else
          Some { wi; dist; value = Color.black;
                 pdf = dist *. dist /. (c *. 4. *. Float.pi *. radius *. radius) }

let pdf e p q nq =
  match e with
  | Delta _ | Area _ -> 0.
  | Sphere { center; radius; _ } ->
      let d = Vec3.dist center p in
      if d > radius then 1. /. (two_pi *. (1. -. cos_max radius d))
      else
        let w = Vec3.sub q p in
        let dist2 = Vec3.length2 w in
        let c = Float.abs (Vec3.dot w nq) /. Float.sqrt dist2 in
        if c <= 0. then 0. else dist2 /. (c *. 4. *. Float.pi *. radius *. radius)

(* a loop, not [Array.find_opt] with a closure made at every call: asked
   at every path vertex that emits *)
let find_index es o =
  let r = ref (-1) and i = ref 0 in
  while !r < 0 && !i < Array.length es do
    (match Array.unsafe_get es !i with Sphere { obj; _ } when obj == o -> r := !i | _ -> ());
    incr i
  done;
  !r

let find es o = match find_index es o with -1 -> None | i -> Some es.(i)

(* [sample]'s sphere in place, the same arithmetic in the same order
   (inlined: its floats stay unboxed; the vector forms allocate a dozen
   records a sample) *)
let[@inline] sphere_into (center : Vec3.t) radius (p : Vec3.m) u v out =
  let tx = center.x -. p.mx and ty = center.y -. p.my and tz = center.z -. p.mz in
  let d = Float.sqrt ((tx *. tx) +. (ty *. ty) +. (tz *. tz)) in
  if d > radius then begin
    let cm = cos_max radius d in
    let c = 1. -. (u *. (1. -. cm)) in
    let s = Float.sqrt (fmax 0. (1. -. (c *. c))) and phi = two_pi *. v in
    (* [Bsdf.basis] of the unit direction to the centre *)
    let k = 1. /. d in
    let nx = k *. tx and ny = k *. ty and nz = k *. tz in
    let sign = Float.copy_sign 1. nz in
    let a = -1. /. (sign +. nz) in
    let b = nx *. ny *. a in
    let t1x = 1. +. (sign *. nx *. nx *. a) and t1y = sign *. b and t1z = -.sign *. nx in
    let t2x = b and t2y = sign +. (ny *. ny *. a) and t2z = -.ny in
    let ka = s *. Float.cos phi and kb = s *. Float.sin phi and kc = c /. d in
    Vec3.set out.wi
      ((ka *. t1x) +. (kb *. t2x) +. (kc *. tx))
      ((ka *. t1y) +. (kb *. t2y) +. (kc *. ty))
      ((ka *. t1z) +. (kb *. t2z) +. (kc *. tz));
    Color.acc_set out.value 0. 0. 0.;
    out.n.dist <- d +. radius;
    out.n.pdf <- 1. /. (two_pi *. (1. -. cm));
    true
  end
  else begin
    let z = 1. -. (2. *. u) in
    let s = Float.sqrt (fmax 0. (1. -. (z *. z))) and phi = two_pi *. v in
    let nx = s *. Float.cos phi and ny = s *. Float.sin phi in
    let wx = center.x +. (radius *. nx) -. p.mx and wy = center.y +. (radius *. ny) -. p.my
    and wz = center.z +. (radius *. z) -. p.mz in
    let dist = Float.sqrt ((wx *. wx) +. (wy *. wy) +. (wz *. wz)) in
    let k = 1. /. dist in
    let ix = k *. wx and iy = k *. wy and iz = k *. wz in
    let c = Float.abs ((ix *. nx) +. (iy *. ny) +. (iz *. z)) in
    c > 0.
    && begin
         Vec3.set out.wi ix iy iz;
         Color.acc_set out.value 0. 0. 0.;
         out.n.dist <- dist;
         out.n.pdf <- dist *. dist /. (c *. 4. *. Float.pi *. radius *. radius);
         true
       end
  end

(* inlined: [u] and [v] are not boxed *)
let[@inline] sample_into e (p : Vec3.m) u v out =
  match e with
  | Delta l ->
      Vec3.load out.pos l.position;
      point_light_into l p out
  | Area { light; area } ->
      Light.position_into light area p (u -. 0.5) (v -. 0.5) out.pos;
      point_light_into light p out
  | Sphere { center; radius; _ } -> sphere_into center radius p u v out

(* [pdf] in place (inlined: nothing boxed) *)
let[@inline] pdf_m e (p : Vec3.m) (q : Vec3.m) (nq : Vec3.m) =
  match e with
  | Delta _ | Area _ -> 0.
  | Sphere { center; radius; _ } ->
      let cx = center.x -. p.mx and cy = center.y -. p.my and cz = center.z -. p.mz in
      let d = Float.sqrt ((cx *. cx) +. (cy *. cy) +. (cz *. cz)) in
      if d > radius then 1. /. (two_pi *. (1. -. cos_max radius d))
      else
        let wx = q.mx -. p.mx and wy = q.my -. p.my and wz = q.mz -. p.mz in
        let dist2 = (wx *. wx) +. (wy *. wy) +. (wz *. wz) in
        let c = Float.abs ((wx *. nq.mx) +. (wy *. nq.my) +. (wz *. nq.mz)) /. Float.sqrt dist2 in
        if c <= 0. then 0. else dist2 /. (c *. 4. *. Float.pi *. radius *. radius)
