type layer = {
  pigment : Pigment.t;
  normal : Normal.t option;
  finish : Finish.t;
  tmap : tmap option;
  uv_texture : bool;
}

and tmap = {
  pattern : Pattern.t;
  entries : (float * t) array;
  xform : Transform.t;
  uv : bool;
  turns : bool;
  frame : Transform.t;
  kind : kind;
}
and kind = Map | Average | Field of { blob : Blob.t; cut : float }
and t = layer list

let layer pigment finish = { pigment; normal = None; finish; tmap = None; uv_texture = false }
let plain pigment finish = [ layer pigment finish ]
let default = plain Pigment.black Finish.default

let patterned pattern entries =
  { (layer Pigment.black Finish.default) with
    tmap =
      Some
        { pattern; entries; xform = Transform.identity; uv = false; turns = false; frame = Transform.identity;
          kind = Map } }

let averaged entries =
  { (layer Pigment.black Finish.default) with
    tmap =
      Some
        { pattern = Pattern.make Pattern.Bozo; entries; xform = Transform.identity; uv = false; turns = false;
          frame = Transform.identity; kind = Average } }

let blob_field blob ~cut xform entries =
  { (layer Pigment.black Finish.default) with
    tmap =
      Some
        { pattern = Pattern.make Pattern.Bozo; entries = Array.map (fun t -> (0., t)) entries; xform; uv = false;
          turns = false; frame = Transform.identity; kind = Field { blob; cut } } }

type weights = { mutable k0 : float; mutable k1 : float }

type pick = {
  mutable n : int;
  mutable t0 : t;
  mutable t1 : t;
  w : weights;
  mutable ws : Float.Array.t;  (* a blob field's shares ... *)
  mutable ix : int array;  (* ... and their entries *)
  q : Vec3.m;  (* the point in the blob's space *)
  tp : Vec3.m;  (* the point the entries are taken at *)
}

let pick () =
  { n = 0; t0 = []; t1 = []; w = { k0 = 0.; k1 = 0. }; ws = Float.Array.make 4 0.; ix = Array.make 4 0; q = Vec3.m ();
    tp = Vec3.m () }

let[@inline] one pk t =
  pk.n <- 1;
  pk.t0 <- t;
  pk.w.k0 <- 1.

(* per domain: the pattern's work *)
let work_key = Scratch.key Pattern.work

(* POV-Ray's textures of a blob's components (blob.cpp's
   Determine_Textures and its use in trace.cpp): each component whose
   field is not zero at the point, by its share; shares below [cut] (the
   scene's adc_bailout) left out, the others not scaled up *)
let field_blend m blob cut (point : Vec3.m) pk =
  let k = Blob.components blob in
  if Float.Array.length pk.ws < k then begin
    pk.ws <- Float.Array.make k 0.;
    pk.ix <- Array.make k 0
  end;
  Transform.inv_point_m m.xform point pk.q;
  let n = Blob.weights blob pk.q pk.ws pk.ix in
  let kept = ref 0 in
  for j = 0 to n - 1 do
    let w = Float.Array.unsafe_get pk.ws j in
    if w >= cut then begin
      Float.Array.unsafe_set pk.ws !kept w;
      Array.unsafe_set pk.ix !kept (Array.unsafe_get pk.ix j);
      incr kept
    end
  done;
  pk.n <- !kept

(* POV-Ray 3.7 (trace.cpp's ComputeOneTextureColour): a map's or a block
   pattern's entries are taken at the point its pattern is evaluated at,
   in its space (its transformations, warps and turbulence applied); an
   average's at the point in its space; a blob's components' textures at
   the point itself *)
let blend_m m (point : Vec3.m) pk =
  match m.kind with
  | Average ->
      let point = if m.uv then Pattern.uv_point () else point in
      Transform.inv_point_m m.xform point pk.tp;
      (* POV-Ray 3.7 warps an average's point: the warps and turbulence
         its pattern carries (its kind unused) *)
      Pattern.warp_in_place m.pattern pk.tp (Scratch.get work_key);
      pk.n <- Array.length m.entries
  | Field { blob; cut } ->
      Vec3.set pk.tp point.mx point.my point.mz;
      field_blend m blob cut point pk
  | Map ->
  let point = if m.uv then Pattern.uv_point () else point in
  let w = Scratch.get work_key in
  let v = Pattern.eval_at m.pattern m.xform point w in
  (let p = Pattern.entries_point m.pattern w in
   Vec3.set pk.tp p.mx p.my p.mz);
  let n = Array.length m.entries in
  if n = 0 then one pk default
  else if Pattern.is_block m.pattern.kind then one pk (snd m.entries.(Int.max 0 (Int.min (n - 1) (int_of_float v))))
  else begin
    let i = Pattern.around m.entries v in
    if i = 0 then one pk (snd m.entries.(0))
    else if i >= n then one pk (snd m.entries.(n - 1))
    else
      let vi, ti = m.entries.(i) and vp, tp = m.entries.(i - 1) in
      if vi -. vp <= 0. then one pk ti
      else begin
        let k = (v -. vp) /. (vi -. vp) in
        pk.n <- 2;
        pk.t0 <- tp;
        pk.t1 <- ti;
        pk.w.k0 <- 1. -. k;
        pk.w.k1 <- k
      end
  end

let[@inline] entry m pk j =
  match m.kind with
  | Map -> if j = 0 then pk.t0 else pk.t1
  | Average -> snd (Array.unsafe_get m.entries j)
  | Field _ -> snd (Array.unsafe_get m.entries (Array.unsafe_get pk.ix j))

let[@inline] weight m pk j =
  match m.kind with
  | Map -> if j = 0 then pk.w.k0 else pk.w.k1
  | Average -> fst (Array.unsafe_get m.entries j)
  | Field _ -> Float.Array.unsafe_get pk.ws j

let heaviest m pk =
  match m.kind with
  | Map -> if pk.n = 2 && pk.w.k1 > pk.w.k0 then pk.t1 else pk.t0
  | Average | Field _ ->
      let best = ref 0 in
      for j = 1 to pk.n - 1 do
        if weight m pk j > weight m pk !best then best := j
      done;
      if pk.n = 0 then [] else entry m pk !best

(* A layer that lets no light through makes the whole texture block it;
   a blob's components' textures block it when they all do *)
let rec blocks_light (t : t) =
  List.exists
    (fun l ->
      match l.tmap with
      | None -> Pigment.opaque l.pigment
      | Some { kind = Field _; entries; _ } -> all_block entries 0
      | Some _ -> false)
    t

(* no Array.for_all: its loop is a closure made at each call (this runs
   for every shadow ray) *)
and all_block entries i = i >= Array.length entries || (blocks_light (snd entries.(i)) && all_block entries (i + 1))

(* POV-Ray: transformations written after a uv-mapped texture (the
   object's) do not move its patterns (measured): a uv pattern's
   transform stays, its uv-mapped pigments ignore them, and its
   uv-mapped normals take them as the frame they tilt the normal in
   (see {!Normal.uv}) *)
(* POV-Ray 3.7 (texture.cpp's Transform_Textures): a patterned layer's
   own pattern moves, its entries follow it (taken in its space, see
   [blend_m]); a blob's components' textures are each moved *)
let rec transform_layer tr l =
  {
    l with
    pigment = Pigment.transform tr l.pigment;
    normal = Option.map (Normal.transform tr) l.normal;
    tmap =
      Option.map
        (fun m ->
          match m.kind with
          | Field _ ->
              { m with xform = Transform.then_ m.xform tr; entries = Array.map (fun (v, t) -> (v, transform tr t)) m.entries }
          | Map | Average ->
              if m.uv then { m with frame = (if m.turns then Transform.then_ m.frame tr else m.frame) }
              else { m with xform = Transform.then_ m.xform tr; frame = Transform.then_ m.frame tr })
        l.tmap;
  }

and transform tr t = List.map (transform_layer tr) t

let rec uv_layer ~turns l =
  {
    l with
    pigment = Pigment.uv l.pigment;
    normal = Option.map (Normal.uv ~turns) l.normal;
    tmap =
      Option.map
        (fun m ->
          match m.kind with
          | Field _ -> { m with entries = Array.map (fun (v, t) -> (v, uv ~turns t)) m.entries }
          (* the pattern taken at the surface's uv; the entries follow it *)
          | Map | Average -> { m with uv = true; turns = m.turns || turns })
        l.tmap;
  }

and uv ~turns t = List.map (uv_layer ~turns) t

(* a texture-level uv_mapping is, to POV-Ray, a pattern of its own *)
let uv_texture t = List.map (fun l -> { l with uv_texture = true }) (uv ~turns:true t)
let is_patterned t = List.exists (fun l -> l.tmap <> None || l.uv_texture) t

let layering ~above ~below =
  if below = [] then None
  else if is_patterned below then Some "cannot layer over a patterned texture"
  else if is_patterned above then Some "cannot layer a patterned texture over another"
  else None

let rec uses_uv t =
  List.exists
    (fun l ->
      match l.tmap with
      | Some m -> m.uv || Array.exists (fun (_, t) -> uses_uv t) m.entries
      | None -> Pigment.uses_uv l.pigment || match l.normal with Some n -> Normal.uses_uv n | None -> false)
    t
