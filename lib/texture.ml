type layer = {
  pigment : Pigment.t;
  normal : Normal.t option;
  finish : Finish.t;
  tmap : tmap option;
  uv_texture : bool;
}

and tmap = { pattern : Pattern.t; entries : (float * t) array; xform : Transform.t; uv : bool; average : bool }
and t = layer list

let layer pigment finish = { pigment; normal = None; finish; tmap = None; uv_texture = false }
let plain pigment finish = [ layer pigment finish ]
let default = plain Pigment.black Finish.default

let patterned pattern entries =
  { (layer Pigment.black Finish.default) with
    tmap = Some { pattern; entries; xform = Transform.identity; uv = false; average = false } }

let averaged entries =
  { (layer Pigment.black Finish.default) with
    tmap = Some { pattern = Pattern.make Pattern.Bozo; entries; xform = Transform.identity; uv = false; average = true } }

type weights = { mutable k0 : float; mutable k1 : float }
type pick = { mutable n : int; mutable t0 : t; mutable t1 : t; w : weights }

let pick () = { n = 0; t0 = []; t1 = []; w = { k0 = 0.; k1 = 0. } }

let[@inline] one pk t =
  pk.n <- 1;
  pk.t0 <- t;
  pk.w.k0 <- 1.

(* per domain: the pattern's work *)
let work_key = Scratch.key Pattern.work

let blend_m m (point : Vec3.m) pk =
  if m.average then pk.n <- Array.length m.entries
  else
  let point = if m.uv then Pattern.uv_point () else point in
  let v = Pattern.eval_at m.pattern m.xform point (Scratch.get work_key) in
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

let[@inline] entry m pk j = if m.average then snd (Array.unsafe_get m.entries j) else if j = 0 then pk.t0 else pk.t1

let[@inline] weight m pk j =
  if m.average then fst (Array.unsafe_get m.entries j) else if j = 0 then pk.w.k0 else pk.w.k1

(* A layer that lets no light through makes the whole texture block it. *)
let blocks_light (t : t) =
  List.exists (fun l -> match l.tmap with None -> Pigment.opaque l.pigment | Some _ -> false) t

(* POV-Ray: transformations written after a uv-mapped texture (the
   object's) do not move its patterns (measured): a uv pattern's
   transform stays, its uv-mapped pigments ignore them, and its
   uv-mapped normals take them as the frame they tilt the normal in
   (see {!Normal.uv}) *)
let rec transform_layer tr l =
  {
    l with
    pigment = Pigment.transform tr l.pigment;
    normal = Option.map (Normal.transform tr) l.normal;
    tmap =
      Option.map
        (fun m ->
          {
            m with
            xform = (if m.uv then m.xform else Transform.then_ m.xform tr);
            entries = Array.map (fun (v, t) -> (v, transform tr t)) m.entries;
          })
        l.tmap;
  }

and transform tr t = List.map (transform_layer tr) t

let rec uv_layer ~turns l =
  {
    l with
    pigment = Pigment.uv l.pigment;
    normal = Option.map (Normal.uv ~turns) l.normal;
    tmap =
      Option.map (fun m -> { m with uv = true; entries = Array.map (fun (v, t) -> (v, uv ~turns t)) m.entries }) l.tmap;
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
