type settings = {
  max_trace_level : int;
  adc_bailout : float;
  ambient_light : Color.t;
  encoding : Image.encoding;
  legacy_alpha : bool;
}

(* [finite] is stored in BVH leaf order. [spheres] holds, per finite
   object, centre and radius when it is a plain sphere (no transform, clip,
   inversion or no_shadow), radius -1 otherwise: those are tested straight from this
   flat array, without following pointers to the object. *)
type accel = { finite : Object.t array; bvh : Bvh.t; infinite : Object.t array; spheres : Float.Array.t }

type t = {
  objects : Object.t array;
  lights : Light.t array;
  camera : Camera.t;
  background : Color.t;
  settings : settings;
  accel : accel;
}

let default_settings =
  {
    max_trace_level = 5;
    adc_bailout = 1. /. 255.;
    ambient_light = Color.white;
    encoding = Image.Srgb;
    legacy_alpha = false;
  }

let accelerate objects =
  let box (o : Object.t) =
    match o.bounds with
    | Some ((lo : Vec3.t), (hi : Vec3.t)) when Vec3.is_finite lo && Vec3.is_finite hi -> Some (lo, hi)
    | _ -> None
  in
  let nonempty ((lo : Vec3.t), (hi : Vec3.t)) = lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z in
  let infinite = List.filter (fun o -> box o = None) (Array.to_list objects) in
  (* empty boxes (an intersection of disjoint solids) are dropped *)
  let n = Array.fold_left (fun n o -> match box o with Some b when nonempty b -> n + 1 | _ -> n) 0 objects in
  let finite = if n = 0 then [||] else Array.make n objects.(0) in
  let boxes = Float.Array.create (6 * n) in
  let k = ref 0 in
  Array.iter
    (fun o ->
      match box o with
      | Some ((lo, hi) as b) when nonempty b ->
          let i = !k in
          finite.(i) <- o;
          Float.Array.set boxes (6 * i) lo.x;
          Float.Array.set boxes ((6 * i) + 1) lo.y;
          Float.Array.set boxes ((6 * i) + 2) lo.z;
          Float.Array.set boxes ((6 * i) + 3) hi.x;
          Float.Array.set boxes ((6 * i) + 4) hi.y;
          Float.Array.set boxes ((6 * i) + 5) hi.z;
          incr k
      | _ -> ())
    objects;
  let bvh, order = Bvh.renumber (Bvh.build boxes) in
  let finite = Array.map (fun i -> finite.(i)) order in
  let spheres = Float.Array.make (4 * Array.length finite) (-1.) in
  Array.iteri
    (fun i (o : Object.t) ->
      match o.geom with
      | Object.Prim (Shape.Sphere { center; radius })
        when Transform.is_identity o.xform && Array.length o.clip = 0 && (not o.inverted) && not o.no_shadow ->
          Float.Array.set spheres (4 * i) center.x;
          Float.Array.set spheres ((4 * i) + 1) center.y;
          Float.Array.set spheres ((4 * i) + 2) center.z;
          Float.Array.set spheres ((4 * i) + 3) radius
      | _ -> ())
    finite;
  { finite; bvh; infinite = Array.of_list infinite; spheres }

let make ~objects ~lights ~camera ~background ~settings =
  { objects; lights; camera; background; settings; accel = accelerate objects }

let bvh_nodes s = Bvh.nodes s.accel.bvh

(* Nearest root in (tmin, tmax) of the sphere stored at [i], or infinity. *)
let[@inline] sphere_root sp i rad (r : Ray.t) tmin tmax =
  let ox = r.origin.x -. Float.Array.unsafe_get sp (4 * i)
  and oy = r.origin.y -. Float.Array.unsafe_get sp ((4 * i) + 1)
  and oz = r.origin.z -. Float.Array.unsafe_get sp ((4 * i) + 2) in
  let dx = r.dir.x and dy = r.dir.y and dz = r.dir.z in
  let a = (dx *. dx) +. (dy *. dy) +. (dz *. dz) in
  let hb = (ox *. dx) +. (oy *. dy) +. (oz *. dz) in
  let c = (ox *. ox) +. (oy *. oy) +. (oz *. oz) -. (rad *. rad) in
  let disc = (hb *. hb) -. (a *. c) in
  if disc < 0. then infinity
  else
    let sq = Float.sqrt disc in
    let q = if hb > 0. then -.(hb +. sq) else -.hb +. sq in
    let t0 = q /. a and t1 = if q = 0. then 0. else c /. q in
    let lo = if t0 < t1 then t0 else t1 and hi = if t0 < t1 then t1 else t0 in
    if lo > tmin && lo < tmax then lo else if hi > tmin && hi < tmax then hi else infinity

type hit = { t : float; obj : Object.t; point : Vec3.t; normal : Vec3.t }

let intersect s r tmin tmax =
  if Array.length s.objects = 0 then None
  else
    let a = s.accel in
    let h = Hit.create tmax and f = Object.found s.objects.(0) in
    let any = ref false in
    for i = 0 to Array.length a.infinite - 1 do
      if Object.hit a.infinite.(i) r tmin h f then any := true
    done;
    let sp = a.spheres in
    Bvh.nearest a.bvh r tmin h (fun i ->
        let rad = Float.Array.unsafe_get sp ((4 * i) + 3) in
        if rad >= 0. then begin
          let t = sphere_root sp i rad r tmin h.t in
          if t < h.t then (
            h.t <- t;
            h.id <- -.float i -. 1.;
            f.leaf <- Array.unsafe_get a.finite i;
            any := true)
        end
        else if Object.hit (Array.unsafe_get a.finite i) r tmin h f then any := true);
    if not !any then None
    else
      let point = Ray.at r h.t in
      let normal =
        if h.id >= 0. then Object.normal f.leaf point h
        else
          (* a flat-array sphere: its normal without touching the object *)
          let i = 4 * int_of_float (-.h.id -. 1.) and sp = a.spheres in
          let k = 1. /. Float.Array.get sp (i + 3) in
          Vec3.make
            ((point.x -. Float.Array.get sp i) *. k)
            ((point.y -. Float.Array.get sp (i + 1)) *. k)
            ((point.z -. Float.Array.get sp (i + 2)) *. k)
      in
      Some { t = h.t; obj = f.leaf; point; normal }

(* Every crossing matters for coloured shadows: each object crossed walks
   all its surface crossings; the BVH skips objects whose box is missed. *)
let occluders s r tmin tmax f =
  let a = s.accel in
  let each (o : Object.t) =
    Object.crossings o r tmin tmax (fun (leaf : Object.t) t -> leaf.no_shadow || f leaf t)
  in
  let sp = a.spheres in
  Array.for_all each a.infinite
  && Bvh.iter a.bvh r tmin tmax (fun i ->
         let rad = Float.Array.unsafe_get sp ((4 * i) + 3) in
         if rad < 0. then each a.finite.(i)
         else
           let t = sphere_root sp i rad r tmin tmax in
           t = infinity
           ||
           let o = a.finite.(i) in
           f o t
              &&
              let t' = sphere_root sp i rad r (Object.next_tmin r t) tmax in
              t' = infinity || f o t')

let occluded s r tmin tmax = not (occluders s r tmin tmax (fun _ _ -> false))
