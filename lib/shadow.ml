(* Shadow rays (see shadow.mli). *)

(* (f*P + t) of a texture at a point, what a surface lets through, into
   [out]: the product over its layers; a texture map's layer blends its
   textures' own. Per domain and nesting depth: the textures picked, their
   sum, the one being summed, a pigment. *)
type filter_level = { fpick : Texture.pick; fsum : Color.acc; fsub : Color.acc; fpig : Pigment.out }

let filter_key =
  Scratch.key (fun () ->
      Scratch.levels ~initial:2 (fun () ->
          { fpick = Texture.pick (); fsum = Color.acc 0.; fsub = Color.acc 0.; fpig = Pigment.out () }))

let filter_level d = Scratch.level (Scratch.get filter_key) d

let rec filter_into (tex : Texture.t) (q : Vec3.m) (out : Color.acc) d =
  Color.acc_set out 1. 1. 1.;
  let rest = ref tex and go = ref true in
  while !go do
    match !rest with
    | [] -> go := false
    | (layer : Texture.layer) :: tl ->
        rest := tl;
        let lv = filter_level d in
        (match layer.tmap with
        | Some m ->
            let pk = lv.fpick and f = lv.fsum and sub = lv.fsub in
            Texture.blend_m m q pk;
            Color.acc_set f 0. 0. 0.;
            for j = 0 to pk.n - 1 do
              filter_into (Texture.entry m pk j) q sub (d + 1);
              let k = Texture.weight m pk j in
              Color.acc_set f (f.ar +. (k *. sub.ar)) (f.ag +. (k *. sub.ag)) (f.ab +. (k *. sub.ab))
            done;
            Color.acc_set out (out.ar *. f.ar) (out.ag *. f.ag) (out.ab *. f.ab)
        | None ->
            let c = lv.fpig in
            Pigment.into layer.pigment q c;
            Color.acc_set out
              (out.ar *. ((c.filter *. c.r) +. c.transmit))
              (out.ag *. ((c.filter *. c.g) +. c.transmit))
              (out.ab *. ((c.filter *. c.b) +. c.transmit)))
  done

(* The walk's state lives in a per-domain record, so that the callback is
   a closed function (no closure and refs per shadow ray); filter_into
   traces nothing, so walks never nest on a domain. [ray] holds the
   shadow ray, [l] the direction to the light being shaded. *)
type length = { mutable len : float }

type walk = {
  acc : Color.acc;  (** the light let through so far *)
  (* the crossings of fading objects, in the order met: the objects and
     their distances *)
  mutable fobjs : Object.t array;
  mutable fts : Float.Array.t;
  mutable nf : int;
  mutable sorted : Float.Array.t;  (** one object's distances, sorted *)
  inside_f : Object.found;  (** a point tested for being inside *)
  ray : Ray.scratch;
  l : Light.dir;
  seg : length;  (** how far the shadow ray goes *)
  (* an area light's average: the light, the scene, the lit point, a
     sample's position, the mean *)
  mutable alight : Light.t;
  mutable aarea : Light.area;
  mutable ascene : Scene.t option;
  lp : Vec3.m;
  q : Vec3.m;
  mean : Color.acc;
  cross : Vec3.m;  (** a crossing of the shadow ray *)
  filter : Color.acc;  (** what the surface there lets through *)
  cn : Vec3.m;  (** the surface's normal there (faked caustics) *)
  pn : Vec3.m;  (** a layer's perturbed normal *)
  mutable air : Media.t list;
      (** the scene's atmospheric media when the light has
          media_attenuation on, else [[]] *)
}

let shadow_key =
  Scratch.key (fun () ->
      { acc = Color.acc 1.; fobjs = [||]; fts = Float.Array.create 0; nf = 0;
        sorted = Float.Array.create 0; inside_f = Object.found (Object.make (Shape.sphere Vec3.zero 1.));
        ray = Ray.scratch (); l = Light.dir (); seg = { len = 0. };
        alight = Light.point Vec3.zero Color.black; aarea = Light.area Vec3.unit_x Vec3.unit_z 1 1;
        ascene = None; lp = Vec3.m (); q = Vec3.m (); mean = Color.acc 0.; cross = Vec3.m ();
        filter = Color.acc 0.; cn = Vec3.m (); pn = Vec3.m (); air = [] })

(* a crossing of a fading object, kept in growing arrays *)
let add_fader w (o : Object.t) (h : Hit.t) =
  let k = w.nf in
  if k = Array.length w.fobjs then begin
    let n = max 4 (2 * k) in
    let objs = Array.make n o and ts = Float.Array.create n in
    Array.blit w.fobjs 0 objs 0 k;
    Float.Array.blit w.fts 0 ts 0 k;
    w.fobjs <- objs;
    w.fts <- ts;
    w.sorted <- Float.Array.create n
  end;
  w.fobjs.(k) <- o;
  Float.Array.set w.fts k h.t;
  w.nf <- k + 1

(* POV-Ray's faked caustics: per layer, more light where the ray meets the
   surface (its normal perturbed by the layer's) square on *)
let caustics w (o : Object.t) q h c =
  let r = w.ray and n = w.cn and pn = w.pn in
  Object.normal_into o q h n;
  let dl = Float.sqrt ((r.dx *. r.dx) +. (r.dy *. r.dy) +. (r.dz *. r.dz)) in
  let k = ref 1. in
  List.iter
    (fun (l : Texture.layer) ->
      (match l.normal with Some nm -> Normal.perturb_m nm q n pn | None -> Vec3.set pn n.mx n.my n.mz);
      let cos = Float.abs ((pn.mx *. r.dx) +. (pn.my *. r.dy) +. (pn.mz *. r.dz)) /. dl in
      k := !k *. (1. +. Float.pow cos c))
    o.texture;
  !k

let shadow_hit (o : Object.t) (h : Hit.t) =
  let t = h.t in
  let w = Scratch.get shadow_key in
  let a = w.acc in
  if Texture.blocks_light o.texture then begin
    Color.acc_set a 0. 0. 0.;
    false
  end
  else begin
    let r = w.ray and q = w.cross and f = w.filter in
    Vec3.set q (r.ox +. (t *. r.dx)) (r.oy +. (t *. r.dy)) (r.oz +. (t *. r.dz));
    filter_into o.texture q f 0;
    let c = o.interior.caustics in
    let k = if c = 0. then 1. else caustics w o q h c in
    Color.acc_set a (a.ar *. k *. f.ar) (a.ag *. k *. f.ag) (a.ab *. k *. f.ab);
    if Interior.fades_light o.interior || o.interior.media <> [] then add_fader w o h;
    not (Color.acc_is_black a)
  end

(* where [shadow_hit] is false whatever the crossing *)
let shadow_opaque (o : Object.t) = Texture.blocks_light o.texture

(* Each object crossed, taken last crossed first: the segments between
   its crossings (and the ray's ends) whose middle is inside it fade what
   passes. Distances of one object sorted in place. *)
let fade_segments (w : walk) dist =
  let r = w.ray and f = w.inside_f in
  let n = w.nf in
  for k = n - 1 downto 0 do
    let o = w.fobjs.(k) in
    (* an object met again later was taken there *)
    let later = ref false in
    for j = k + 1 to n - 1 do
      if w.fobjs.(j) == o then later := true
    done;
    if not !later then begin
      let ts = w.sorted and m = ref 0 in
      for j = n - 1 downto 0 do
        if w.fobjs.(j) == o then begin
          (* insertion, ascending *)
          let t = Float.Array.get w.fts j in
          let i = ref !m in
          while !i > 0 && Float.Array.get ts (!i - 1) > t do
            Float.Array.set ts !i (Float.Array.get ts (!i - 1));
            decr i
          done;
          Float.Array.set ts !i t;
          incr m
        end
      done;
      let inner = o.interior and fc = o.interior.fade_color and a = w.acc in
      for j = 0 to !m do
        let lo = if j = 0 then 0. else Float.Array.get ts (j - 1) in
        let hi = if j = !m then dist else Float.Array.get ts j in
        if hi > lo then begin
          let mid = 0.5 *. (lo +. hi) in
          let p = f.pt in
          p.ox <- r.ox +. (mid *. r.dx);
          p.oy <- r.oy +. (mid *. r.dy);
          p.oz <- r.oz +. (mid *. r.dz);
          if Object.inside_s o f then begin
            let d = hi -. lo in
            if Interior.fades_light inner then
              Color.acc_set a
                (a.ar *. Interior.fade_channel inner fc.r d)
                (a.ag *. Interior.fade_channel inner fc.g d)
                (a.ab *. Interior.fade_channel inner fc.b d);
            (* the interior's media dim the light (POV-Ray 3.7 does so
               whatever the light's media_attenuation) *)
            if inner.media <> [] then Media.transmittance_into inner.media r lo hi a
          end
        end
      done
    end
  done

(* Light reaching the origin of the walk's ray from [w.seg.len] along its
   unit direction: the product of (f*P + t) of every surface crossed, with
   interior fade over the lengths travelled inside fading objects; black
   when something opaque blocks. Left in [w.acc]: stored in the walk's
   own fields, nothing is allocated or written through [caml_modify]
   unless a crossing lets light through. *)
let shadow_into (s : Scene.t) (w : walk) =
  let dist = w.seg.len in
  Color.acc_set w.acc 1. 1. 1.;
  w.nf <- 0;
  w.ray.far <- dist;
  let visible = Scene.occluders_s s w.ray Ray.shadow_epsilon shadow_opaque shadow_hit in
  if not visible then Color.acc_set w.acc 0. 0. 0.
  else begin
    if w.nf > 0 then fade_segments w dist;
    (* atmospheric media: over the whole shadow ray, inside solids too
       (POV-Ray 3.7 does so, measured: a clear solid box on the way
       dims the light as much as a hollow one) *)
    if w.air <> [] then Media.transmittance_into w.air w.ray 0. dist w.acc
  end

(* Sample (i, j) of the area light in [w]: the shadow colour from its
   point, seen from [w.lp] *)
let area_sample (w : walk) i j (out : Color.acc) =
  let light = w.alight and a = w.aarea and p = w.lp and q = w.q in
  Light.position_into light a p (Light.offset a.n1 i) (Light.offset a.n2 j) q;
  let vx = q.mx -. p.mx and vy = q.my -. p.my and vz = q.mz -. p.mz in
  let d = Float.sqrt ((vx *. vx) +. (vy *. vy) +. (vz *. vz)) in
  let k = 1. /. d in
  Ray.set w.ray p (k *. vx) (k *. vy) (k *. vz);
  w.seg.len <- d;
  (match w.ascene with Some s -> shadow_into s w | None -> ());
  Color.acc_set out w.acc.ar w.acc.ag w.acc.ab

(* The shadow colour at [p] of a point light whose direction is in [w.l],
   into [w.acc] *)
(* POV-Ray dims shadow rays by atmospheric media only for lights with
   media_attenuation on *)
let[@inline] aim (s : Scene.t) (w : walk) (light : Light.t) =
  match s.atmosphere with
  | [] -> if w.air != [] then w.air <- []
  | (i : Interior.t) :: _ ->
      let a = if light.media_attenuation then i.media else [] in
      if w.air != a then w.air <- a

let point s (w : walk) (light : Light.t) (p : Vec3.m) =
  aim s w light;
  let l = w.l in
  Ray.set w.ray p l.lx l.ly l.lz;
  w.seg.len <- l.dist;
  shadow_into s w

(* Shadow colour of one light at [p], whose direction is in [w.l], into
   [w.acc]: area lights average their samples. *)
let light s (w : walk) (light : Light.t) (p : Vec3.m) =
  match light.area with
  | None -> point s w light p
  | Some a ->
      if w.alight != light then w.alight <- light;
      if w.aarea != a then w.aarea <- a;
      (match w.ascene with Some s' when s' == s -> () | _ -> w.ascene <- Some s);
      aim s w light;
      Vec3.set w.lp p.mx p.my p.mz;
      Light.average_area_into a w area_sample w.mean;
      let c = w.mean in
      Color.acc_set w.acc c.ar c.ag c.ab

let walk () = Scratch.get shadow_key
let[@inline] toward w = w.l
let[@inline] passed w = w.acc
