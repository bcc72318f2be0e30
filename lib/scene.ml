type settings = {
  max_trace_level : int;
  adc_bailout : float;
  ambient_light : Color.t;
  encoding : Image.encoding;
  legacy_alpha : bool;
  irid_wavelength : Color.t;
  radiosity : Radiosity.t option;
  photons : Photon.settings option;
  object_media : bool;
}

(* [finite] is stored in BVH leaf order. [spheres] holds, per finite
   object, centre and radius when it is a plain sphere (no transform, clip,
   inversion or no_shadow), radius -1 otherwise: those are tested straight from this
   flat array, without following pointers to the object. *)
type accel = {
  finite : Object.t array;
  bvh : Bvh.t;
  infinite : Object.t array;
  spheres : Float.Array.t;
  reach : Object.t array;  (** objects whose inside reaches beyond their box in the BVH, or without one *)
}

type t = {
  objects : Object.t array;
  lights : Light.t array;
  light_sets : Light.t array array;
  camera : Camera.t;
  background : Color.t;
  sky : Sky.t;
  fog : Fog.t list;
  rainbows : Rainbow.t list;
  atmosphere : Interior.t list;
  settings : settings;
  accel : accel;
  all : accel;
  views : views;
}

and views = { mutable image : t option; mutable reflected : t option; mutable gather : t option }

let default_settings =
  {
    max_trace_level = 5;
    adc_bailout = 1. /. 255.;
    ambient_light = Color.white;
    encoding = Image.Srgb;
    legacy_alpha = false;
    irid_wavelength = Color.make 0.70 0.52 0.48;
    radiosity = None;
    photons = None;
    object_media = true;
  }

(* What testing an object costs, in tests of a sphere held in the flat
   array (the BVH packs cheap objects into leaves of up to 16 and keeps
   dear ones apart; see [accelerate]) *)
let flat_sphere (o : Object.t) =
  match o.geom with
  | Object.Prim (Shape.Sphere _) ->
      Transform.is_identity o.xform && Array.length o.clip = 0 && Array.length o.bound = 0 && (not o.inverted)
      && not o.no_shadow
  | _ -> false

let test_cost (o : Object.t) =
  if flat_sphere o then 1.
  else
    let own =
      (if Transform.is_identity o.xform && Array.length o.clip = 0 then 0. else 1.)
      +. float (2 * Array.length o.bound)
    in
    own
    +.
    match o.geom with
    | Object.Prim (Shape.Sphere _ | Shape.Plane _ | Shape.Box _ | Shape.Disc _ | Shape.Triangle _) -> 2.
    | Object.Prim (Shape.Cone _ | Shape.Smooth_triangle _) -> 3.
    | Object.Prim (Shape.Polygon pg) -> 2. +. float (Polygon.edges pg)
    | Object.Prim (Shape.Torus _) -> 16.
    | Object.Prim (Shape.Height_field _) -> 16.
    | Object.Prim (Shape.Algebraic a) -> 8. *. float (Algebraic.order a)
    | Object.Prim (Shape.Text t) -> 8. *. float (Text.glyph_count t)
    | Object.Prim (Shape.Blob _) -> 32.
    | Object.Prim (Shape.Prism _ | Shape.Lathe _ | Shape.Sor _ | Shape.Superellipsoid _) -> 32.
    | Object.Prim (Shape.Julia _) -> 64.
    | Object.Prim (Shape.Isosurface _) -> 64.
    | Object.Prim (Shape.Mesh _) | Object.Union _ | Object.Merge _ | Object.Intersection _ -> 8.

(* every interior a ray can enter numbered for [Interior.beyond]'s caches *)
let rec number (o : Object.t) =
  Interior.number o.interior;
  match o.geom with Prim _ -> () | Union a | Intersection a | Merge a -> Array.iter number a

let accelerate ?par objects =
  Array.iter number objects;
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
  (* A node's walk costs 2 flat-sphere tests while the tree stays in
     cache, more once its nodes are fetched from memory: 2 up to 2^14
     objects, rising to 8 at 2^20. Measured (trace, one domain): 10^6
     spheres 0.141-0.149 s with 2, 0.114-0.124 s with 8; 10^3 spheres
     0.030-0.032 s with 2, 0.033-0.034 s with 8; the snowman (10 objects)
     0.49-0.52 s with 2 or with 1 (the old tree), 0.61-0.64 s with 8 (one
     leaf of all); RTIOW in mc mode (485 spheres) 5% faster with 2 than
     with 1. *)
  let node_cost =
    let n = float (Array.length finite) in
    Float.min 8. (Float.max 2. (Float.log2 n -. 12.))
  in
  let cost = Float.Array.init (Array.length finite) (fun i -> test_cost finite.(i)) in
  let bvh, order = Bvh.renumber (Bvh.build ~leaf_size:16 ~node_cost ~cost ?par boxes) in
  let finite = Array.map (fun i -> finite.(i)) order in
  let spheres = Float.Array.make (4 * Array.length finite) (-1.) in
  Array.iteri
    (fun i (o : Object.t) ->
      match o.geom with
      | Object.Prim (Shape.Sphere { center; radius }) when flat_sphere o ->
          Float.Array.set spheres (4 * i) center.x;
          Float.Array.set spheres ((4 * i) + 1) center.y;
          Float.Array.set spheres ((4 * i) + 2) center.z;
          Float.Array.set spheres ((4 * i) + 3) radius
      | _ -> ())
    finite;
  (* where a shape's inside is its box's, [solid_box] gives [bounds] itself *)
  let beyond (o : Object.t) = let b = Object.solid_box o in b != o.bounds && b <> o.bounds in
  let in_bvh o = match box o with Some b -> nonempty b | None -> false in
  let reach = List.filter (fun o -> (not (in_bvh o)) || beyond o) (Array.to_list objects) in
  { finite; bvh; infinite = Array.of_list infinite; spheres; reach = Array.of_list reach }

let atmosphere = function
  | [] -> []
  | media ->
      let i = { Interior.default with hollow = true; media } in
      Interior.number i;
      [ i ]

let make ?(sky = Sky.none) ?(fog = []) ?(rainbows = []) ?(media = []) ?(groups = [||]) ~objects ~lights ~camera ~background ~settings () =
  let atmosphere = atmosphere media in
  let accel = accelerate objects in
  { objects; lights; light_sets = Array.append [| lights |] groups; camera; background; sky; fog; rainbows; atmosphere; settings; accel; all = accel;
    views = { image = None; reflected = None; gather = None } }

let with_objects s objects accel = { s with objects; accel; all = accel; views = { image = None; reflected = None; gather = None } }

(* the scene seen without the objects whose [flags] have [bit]: its own
   tree for nearest hits, the whole one for shadows and insides *)
let without s flags bit =
  if Array.for_all (fun f -> f land bit = 0) flags then None
  else
    let keep = List.filteri (fun i _ -> flags.(i) land bit = 0) (Array.to_list s.objects) in
    Some { s with accel = accelerate (Array.of_list keep) }

let hide s flags =
  if Array.length flags <> Array.length s.objects then invalid_arg "Scene.hide";
  let v = { image = None; reflected = None; gather = None } in
  let s = { s with accel = s.all; views = v } in
  (* set both: a view's own fallback would be itself, not the whole scene *)
  v.image <- Some (Option.value ~default:s (without s flags 1));
  v.reflected <- Some (Option.value ~default:s (without s flags 2));
  (match s.settings.radiosity with
  | None -> ()
  | Some r ->
      (* what gather rays see: POV-Ray's radiosity rays skip area lights'
         grids (quality flags without area lights) and, unless media on,
         media, the atmosphere's and the objects' (measured: a floor under
         a hollow shell of emitting media gathers 0, 0.5 with media on);
         their ADC bailout is the radiosity's *)
      let point (l : Light.t) = match l.area with None -> l | Some _ -> { l with area = None } in
      let rv = { image = None; reflected = None; gather = None } in
      let g =
        { s with
          lights = Array.map point s.lights;
          light_sets = Array.map (Array.map point) s.light_sets;
          atmosphere = (if r.media then s.atmosphere else []);
          settings = { s.settings with adc_bailout = r.adc_bailout; object_media = r.media };
          views = rv }
      in
      let g = Option.value ~default:g (without g flags 16) in
      rv.image <- Some g;
      rv.gather <- Some g;
      rv.reflected <- Some (Option.value ~default:g (without s flags (16 lor 2) |> Option.map (fun (x : t) -> { g with accel = x.accel })));
      v.gather <- Some g);
  s

let image s = match s.views.image with Some v -> v | None -> s
let reflected s = match s.views.reflected with Some v -> v | None -> s
let radiosity s = match s.views.gather with Some v -> v | None -> s

let bvh_nodes s = Bvh.nodes s.accel.bvh

(* Nearest root in (tmin, tmax) of the sphere stored at [i], or infinity
   (POV-Ray's arithmetic, as [Shape]'s sphere). *)
let[@inline] sphere_root sp i rad (r : Ray.scratch) tmin tmax =
  Shape.sphere_nearest (Float.Array.unsafe_get sp (4 * i)) (Float.Array.unsafe_get sp ((4 * i) + 1))
    (Float.Array.unsafe_get sp ((4 * i) + 2)) rad r tmin tmax

(* Per-domain scratch for queries: the ray, the hit, where the leaf goes,
   and the callback of [occluders]. [busy] guards against a query started
   from inside another one's callback (it then gets fresh scratch). *)
type scratch = {
  ray : Ray.scratch;
  h : Hit.t;
  f : Object.found;
  mutable occ : Object.t -> Hit.t -> bool;
  mutable opaque : Object.t -> bool;  (** [occ] is false at every crossing *)
  mutable busy : bool;
  stack : Bvh.stack;  (** the traversal stack of the domain that made the record *)
}

let dummy = Object.make (Shape.sphere Vec3.zero 1.)
let new_scratch () = { ray = Ray.scratch (); h = Hit.create 0.; f = Object.found dummy; occ = (fun _ _ -> false);
                       opaque = Object.never; busy = false; stack = Bvh.stack () }
let scratch_key = Scratch.key new_scratch

type query = scratch

let query = new_scratch

let[@inline] take () =
  let sc = Scratch.get scratch_key in
  if sc.busy then new_scratch () else (sc.busy <- true; sc)

let nearest_leaf a (f : Object.found) r tmin (h : Hit.t) i =
  let rad = Float.Array.unsafe_get a.spheres ((4 * i) + 3) in
  if rad >= 0. then begin
    let t = sphere_root a.spheres i rad r tmin h.t in
    if t < h.t then (
      h.t <- t;
      h.id <- -.float i -. 1.;
      true)
    else false
  end
  else Object.hit_s (Array.unsafe_get a.finite i) r tmin h f

let[@inline never] nearest_in s st (r : Ray.scratch) tmin (h : Hit.t) f =
  let a = s.accel in
  let any = ref false in
  for i = 0 to Array.length a.infinite - 1 do
    if Object.hit_s (Array.unsafe_get a.infinite i) r tmin h f then any := true
  done;
  let found = Bvh.nearest_st st a.bvh r tmin h a f nearest_leaf in
  (* a sphere from the flat array: its object is looked up once, for the
     nearest, not at every closer candidate (at 10^6 spheres, a read of
     memory out of cache each) *)
  if found && h.id < 0. then begin
    (* written only when it changes: a write is a call of caml_modify *)
    let o = Array.unsafe_get a.finite (int_of_float (-.h.id -. 1.)) in
    if f.leaf != o then f.leaf <- o
  end;
  found || !any

let nearest s r tmin h f = Array.length s.objects > 0 && nearest_in s (Bvh.stack ()) r tmin h f

type hit = { t : float; obj : Object.t; point : Vec3.t; normal : Vec3.t }

(* the nearest hit of the ray loaded in [sc] *)
let[@inline] nearest_loaded s sc tmin tmax (h : Hit.t) f =
  h.t <- tmax;
  h.u <- 0.;
  h.v <- 0.;
  h.id <- 0.;
  (* a query of the scene starts with no floor (walks restore theirs) *)
  h.floor <- neg_infinity;
  let found = nearest_in s sc.stack sc.ray tmin h f in
  sc.busy <- false;
  found

let[@inline] intersect_with s sc (o : Vec3.m) (d : Vec3.m) tmin tmax (h : Hit.t) (f : Object.found) =
  Array.length s.objects > 0
  && begin
       Ray.set sc.ray o d.mx d.my d.mz;
       nearest_loaded s sc tmin tmax h f
     end

let intersect_into s (o : Vec3.m) (d : Vec3.m) tmin tmax (h : Hit.t) (f : Object.found) =
  Array.length s.objects > 0 && intersect_with s (take ()) o d tmin tmax h f

let hit_normal s (f : Object.found) (h : Hit.t) (point : Vec3.t) =
  if h.id >= 0. then Object.normal f.leaf point h
  else
    (* a flat-array sphere: its normal without touching the object *)
    let i = 4 * int_of_float (-.h.id -. 1.) and sp = s.accel.spheres in
    let k = 1. /. Float.Array.get sp (i + 3) in
    Vec3.make
      ((point.x -. Float.Array.get sp i) *. k)
      ((point.y -. Float.Array.get sp (i + 1)) *. k)
      ((point.z -. Float.Array.get sp (i + 2)) *. k)

let hit_normal_into s (f : Object.found) (h : Hit.t) (point : Vec3.m) (out : Vec3.m) =
  if h.id >= 0. then Object.normal_into f.leaf point h out
  else
    let i = 4 * int_of_float (-.h.id -. 1.) and sp = s.accel.spheres in
    let k = 1. /. Float.Array.get sp (i + 3) in
    Vec3.set out
      ((point.mx -. Float.Array.get sp i) *. k)
      ((point.my -. Float.Array.get sp (i + 1)) *. k)
      ((point.mz -. Float.Array.get sp (i + 2)) *. k)

(* per domain: read before the next query *)
let new_records () = (Hit.create 0., Object.found dummy)
let records_key = Scratch.key new_records
let hit_records () = Scratch.get records_key

let intersect s (r : Ray.t) tmin tmax =
  let h, f = hit_records () in
  let found =
    Array.length s.objects > 0
    &&
    let sc = take () in
    Ray.load sc.ray r;
    nearest_loaded s sc tmin tmax h f
  in
  if not found then None
  else
    let point = Ray.at r h.t in
    Some { t = h.t; obj = f.leaf; point; normal = hit_normal s f h point }

(* Every crossing matters for coloured shadows: each object crossed walks
   all its surface crossings; the BVH skips objects whose box is missed. *)
let occluder_leaf a sc (r : Ray.scratch) tmin i =
  let sp = a.spheres in
  let rad = Float.Array.unsafe_get sp ((4 * i) + 3) in
  if rad < 0. then
    Object.crossings_s (Array.unsafe_get a.finite i) r tmin sc.h sc.f true sc.opaque sc.occ
  else
    let tmax = r.far in
    let t = sphere_root sp i rad r tmin tmax in
    t = infinity
    ||
    let o = Array.unsafe_get a.finite i in
    (* an opaque sphere stops the walk without [occ]; [occ] reads the
       distance in the hit record *)
    (not (sc.opaque o))
    && (sc.h.t <- t;
        sc.occ o sc.h)
    &&
    let t' = sphere_root sp i rad r (Object.next_tmin_s r t) tmax in
    t' = infinity
    || (sc.h.t <- t';
        sc.occ o sc.h)

(* within (tmin, sc.ray.far) *)
let occluders_in s sc tmin opaque g =
  let a = s.all in
  (* written only when they change (ray after ray they are the same
     closed functions, and each write is a [caml_modify]); the last ones
     stay until the next query *)
  if sc.occ != g then sc.occ <- g;
  if sc.opaque != opaque then sc.opaque <- opaque;
  sc.h.floor <- neg_infinity;
  let ok = ref true and i = ref 0 in
  while !ok && !i < Array.length a.infinite do
    ok := Object.crossings_s (Array.unsafe_get a.infinite !i) sc.ray tmin sc.h sc.f true opaque g;
    incr i
  done;
  let ok = !ok && Bvh.iter_st sc.stack a.bvh sc.ray tmin a sc occluder_leaf in
  sc.busy <- false;
  ok

let occluders s r tmin tmax opaque g =
  let sc = take () in
  Ray.load sc.ray r;
  sc.ray.far <- tmax;
  occluders_in s sc tmin opaque (fun o (h : Hit.t) -> g o h.t)

(* the same from a ray in a scratch record of the caller's, up to its
   [far], with the caller's query records ([occluders_s]: the domain's) *)
let occluders_with s sc (r : Ray.scratch) tmin opaque g =
  Ray.copy r sc.ray;
  occluders_in s sc tmin opaque g

let occluders_s s r tmin opaque g = occluders_with s (take ()) r tmin opaque g

(* objects held in a growing array *)
type objects = { mutable items : Object.t array; mutable n : int }

let objects () = { items = [||]; n = 0 }

let[@inline] mem_objects (l : objects) o =
  let i = ref 0 in
  while !i < l.n && Array.unsafe_get l.items !i != o do
    incr i
  done;
  !i < l.n

let add_object (l : objects) o =
  if l.n = Array.length l.items then begin
    let a = Array.make (max 4 (2 * l.n)) o in
    Array.blit l.items 0 a 0 l.n;
    l.items <- a
  end;
  l.items.(l.n) <- o;
  l.n <- l.n + 1

let same_objects (a : objects) (b : objects) =
  a.n = b.n
  &&
  let i = ref 0 in
  while !i < a.n && a.items.(!i) == b.items.(!i) do
    incr i
  done;
  !i = a.n

(* Inside tests at one point: the objects that reach beyond their boxes,
   then those whose box holds the point (a walk of the BVH along a ray of
   no length); per domain, nothing allocated but to grow the arrays *)
type probe = { at : Ray.scratch; pf : Object.found; hits : objects }

let probe_key = Scratch.key (fun () -> { at = Ray.scratch (); pf = Object.found dummy; hits = objects () })

let[@inline] probe_test pr o = if Object.inside_s o pr.pf && not (mem_objects pr.hits o) then add_object pr.hits o

let probe_leaf a pr _ _ i =
  probe_test pr (Array.unsafe_get a.finite i);
  true

let containing_into s (p : Vec3.m) (out : objects) =
  let a = s.all in
  let pr = Scratch.get probe_key in
  let r = pr.at and hits = pr.hits in
  hits.n <- 0;
  Ray.set pr.pf.pt p 0. 0. 1.;
  Ray.set r p 1. 0. 0.;
  r.far <- 0.;
  for i = 0 to Array.length a.reach - 1 do
    probe_test pr (Array.unsafe_get a.reach i)
  done;
  ignore (Bvh.iter_s a.bvh r 0. a pr probe_leaf);
  out.n <- 0;
  if hits.n = 1 then add_object out hits.items.(0)
  else if hits.n > 1 then
    (* the scene's order, last first *)
    for i = Array.length s.objects - 1 downto 0 do
      let o = s.objects.(i) in
      if mem_objects hits o then add_object out o
    done

let containing_m s p =
  let out = objects () in
  containing_into s p out;
  List.init out.n (fun i -> out.items.(i))

let containing s (p : Vec3.t) =
  let pm = Vec3.m () in
  Vec3.load pm p;
  containing_m s pm

let block _ _ = false
let always _ = true
let occluded s r tmin tmax = not (occluders s r tmin tmax always block)

(* each light once, the global ones first: a light shared by two sets is
   one light *)
let all_lights s =
  let acc = ref [] in
  Array.iter
    (Array.iter (fun l -> if not (List.exists (fun l' -> l' == l) !acc) then acc := l :: !acc))
    s.light_sets;
  Array.of_list (List.rev !acc)
