type settings = {
  max_trace_level : int;
  adc_bailout : float;
  ambient_light : Color.t;
  encoding : Image.encoding;
  legacy_alpha : bool;
}

type accel = { finite : Object.t array; bvh : Bvh.t; infinite : Object.t array }

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
  let bounded, infinite =
    List.partition_map
      (fun (o : Object.t) ->
        match o.bounds with
        | Some ((lo : Vec3.t), (hi : Vec3.t)) when Vec3.is_finite lo && Vec3.is_finite hi ->
            if lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z then Left (Some (o, lo, hi))
            else Left None (* empty: an intersection of disjoint solids *)
        | _ -> Right o)
      (Array.to_list objects)
  in
  let finite = Array.of_list (List.filter_map Fun.id bounded) in
  let boxes = Float.Array.create (6 * Array.length finite) in
  Array.iteri
    (fun i (_, (lo : Vec3.t), (hi : Vec3.t)) ->
      List.iteri (fun k v -> Float.Array.set boxes ((6 * i) + k) v) [ lo.x; lo.y; lo.z; hi.x; hi.y; hi.z ])
    finite;
  { finite = Array.map (fun (o, _, _) -> o) finite; bvh = Bvh.build boxes; infinite = Array.of_list infinite }

let bvh_nodes s = Bvh.nodes s.accel.bvh

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
    Bvh.nearest a.bvh r tmin h (fun i -> if Object.hit (Array.unsafe_get a.finite i) r tmin h f then any := true);
    if not !any then None
    else
      let point = Ray.at r h.t in
      Some { t = h.t; obj = f.leaf; point; normal = Object.normal f.leaf point h }

(* Every crossing matters for coloured shadows: each object crossed walks
   all its surface crossings; the BVH skips objects whose box is missed. *)
let occluders s r tmin tmax f =
  let a = s.accel in
  let each (o : Object.t) =
    Object.crossings o r tmin tmax (fun (leaf : Object.t) t -> leaf.no_shadow || f leaf t)
  in
  Array.for_all each a.infinite && Bvh.iter a.bvh r tmin tmax (fun i -> each a.finite.(i))

let occluded s r tmin tmax = not (occluders s r tmin tmax (fun _ _ -> false))
