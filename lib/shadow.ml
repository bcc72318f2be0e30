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
              filter_into (Texture.entry m pk j) pk.tp sub (d + 1);
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
  mutable order : int array;  (** the crossings by distance *)
  mutable inside : Interior.t array;
      (** the interiors the ray is in along the stretch being walked *)
  mutable ni : int;
  mutable ending : Interior.t;
      (** the interior of the object whose crossing ends the stretch
          being walked ([Interior.default] toward the light) *)
  mutable last : bool;  (** the stretch walked is the last, to the light *)
  mutable start : Interior.t list;
      (** the interiors the shadow ray starts in: those of the ray whose
          hit it lights, as POV-Ray copies them into its shadow ray *)
  mutable start_media : bool;  (** some interior of [start] has media *)
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
  uv : Vec3.m;  (** the crossing's uv, for a uv-mapped texture *)
  mutable air : Media.t list;
      (** the scene's atmospheric media when the light has
          media_attenuation on, else [[]] *)
  mutable fogs : Fog.t list;
      (** the scene's fogs when the light has media_attenuation and
          media_interaction on, else [[]] *)
  fo : Vec3.m;  (** where a stretch of fog starts *)
  fd : Vec3.m;  (** the shadow ray's direction, for the fogs *)
  sp : Media.span;  (** the stretch being dimmed *)
  sl : Light.dir;  (** an area light's sample's direction *)
  ax : Light.axes;  (** the area light's axes seen from [lp] *)
  query : Scene.query;  (** the records of the shadow rays' queries of the scene *)
  mutable through : Object.t option;  (** the light's projected_through object *)
  mutable occlude : bool;  (** the light casts shadows (it is not shadowless) *)
  ph : Hit.t;  (** the crossing of the projected_through object *)
  pf : Object.found;
  mutable collecting : bool;  (** the lit surface gathers photons ({!collects}) *)
  mutable lphotons : Photon.flags;  (** the photons words of the light walked to *)
}

let shadow_key =
  Scratch.key (fun () ->
      { acc = Color.acc 1.; fobjs = [||]; fts = Float.Array.create 0; nf = 0;
        order = [||]; inside = [||]; ni = 0; ending = Interior.default; last = false; start = []; start_media = false;
        ray = Ray.scratch (); l = Light.dir (); seg = { len = 0. };
        alight = Light.point Vec3.zero Color.black; aarea = Light.area Vec3.unit_x Vec3.unit_z 1 1;
        ascene = None; lp = Vec3.m (); q = Vec3.m (); mean = Color.acc 0.; cross = Vec3.m ();
        filter = Color.acc 0.; cn = Vec3.m (); pn = Vec3.m (); uv = Vec3.m (); air = []; fogs = []; fo = Vec3.m ();
        fd = Vec3.m (); sp = Media.span (); sl = Light.dir (); ax = Light.axes (); query = Scene.query (); through = None; occlude = true;
        ph = Hit.create infinity; pf = Object.found (Object.make (Shape.sphere Vec3.zero 1.)); collecting = false;
        lphotons = Photon.none })

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
    w.order <- Array.make n 0;
    w.inside <- Array.make n o.interior
  end;
  w.fobjs.(k) <- o;
  Float.Array.set w.fts k h.t;
  w.nf <- k + 1

(* POV-Ray's faked caustics: per layer, more light where the ray meets the
   surface (its normal, turned against the ray, perturbed by the layer's)
   square on; the light
   carried, [w.acc], scaled in place *)
(* a loop, not List.iter: its closure over a float ref allocated both per
   shadow ray (3 words a camera ray on caustics.pov); the factor not
   returned: a float returned from a function not inlined is boxed (0.4
   words a camera ray) *)
let caustics w (o : Object.t) (tex : Texture.t) q h c =
  let r = w.ray and n = w.cn and pn = w.pn in
  Object.normal_into o q h n;
  (* POV-Ray (ComputeShadowColour) turns the normal against the shadow
     ray before perturbing it: the perturbation adds to it, so its side
     matters *)
  if (n.mx *. r.dx) +. (n.my *. r.dy) +. (n.mz *. r.dz) > 0. then Vec3.set n (-.n.mx) (-.n.my) (-.n.mz);
  let dl = Float.sqrt ((r.dx *. r.dx) +. (r.dy *. r.dy) +. (r.dz *. r.dz)) in
  let k = ref 1. and rest = ref tex in
  while (match !rest with [] -> false | _ -> true) do
    match !rest with
    | [] -> ()
    | (l : Texture.layer) :: tl ->
        (match l.normal with Some nm -> Normal.perturb_m nm q n pn | None -> Vec3.set pn n.mx n.my n.mz);
        let cos = Float.abs ((pn.mx *. r.dx) +. (pn.my *. r.dy) +. (pn.mz *. r.dz)) /. dl in
        k := !k *. (1. +. Float.pow cos c);
        rest := tl
  done;
  let a = w.acc in
  Color.acc_set a (a.ar *. !k) (a.ag *. !k) (a.ab *. !k)

let shadow_hit (o : Object.t) (h : Hit.t) =
  let t = h.t in
  let w = Scratch.get shadow_key in
  let a = w.acc in
  let r = w.ray and q = w.cross and f = w.filter in
  Vec3.set q (r.ox +. (t *. r.dx)) (r.oy +. (t *. r.dy)) (r.oz +. (t *. r.dz));
  (* the interior_texture where the ray leaves the solid, as POV-Ray's
     ComputeShadowColour picks it (measured: a sphere whose outer texture
     has clear stripes and whose interior_texture is opaque casts a full
     shadow) *)
  let tex = Object.crossed_texture o q h r w.cn in
  if Texture.blocks_light tex || (w.collecting && Photon.blocks_shadow o.photon ~light:w.lphotons) then begin
    Color.acc_set a 0. 0. 0.;
    false
  end
  else begin
    (* a uv-mapped texture reads the crossing's uv (the shading this
       shadow ray serves has read its own already) *)
    if o.uv then begin
      Object.uv_into o q h w.uv;
      Pattern.set_uv w.uv.mx w.uv.my
    end;
    filter_into tex q f 0;
    let c = o.interior.caustics in
    if c <> 0. then caustics w o tex q h c;
    Color.acc_set a (a.ar *. f.ar) (a.ag *. f.ag) (a.ab *. f.ab);
    (* where the ray starts in media, every crossing ends a stretch:
       POV-Ray computes the media it runs in up to each surface it
       crosses, and not beyond the last *)
    if Interior.fades_light o.interior || o.interior.media <> [] || w.start_media
       || (w.fogs != [] && not o.interior.hollow)
    then add_fader w o h;
    not (Color.acc_is_black a)
  end

(* where [shadow_hit] is false whatever the crossing: both sides block *)
let shadow_opaque (o : Object.t) =
  Texture.blocks_light o.texture && (o.back == o.texture || Texture.blocks_light o.back)

let[@inline] index_in (w : walk) (i : Interior.t) =
  let k = ref (-1) in
  for j = 0 to w.ni - 1 do
    if w.inside.(j) == i then k := j
  done;
  !k

(* The ray crosses into or out of [i]: in POV-Ray's way, an interior
   the ray is in is left, any other entered *)
let toggle (w : walk) (i : Interior.t) =
  let k = index_in w i in
  if k < 0 then begin
    w.inside.(w.ni) <- i;
    w.ni <- w.ni + 1
  end
  else begin
    w.inside.(k) <- w.inside.(w.ni - 1);
    w.ni <- w.ni - 1
  end

(* What a stretch [w.sp] of the shadow ray takes from the light: the
   media of the interiors it runs in, the fade of the object whose
   crossing ends it when the ray leaves that object there (POV-Ray's
   ComputeShadowTexture: a ray leaving a solid through a clipped-away
   hole, or an outer solid through an inner one's surface, is not faded
   by it there), and, in the open (inside hollow objects only), the fogs
   (the ends are read from the walk: float arguments would be boxed) *)
let stretch (w : walk) =
  let a = w.acc and r = w.ray in
  let lo = w.sp.lo and hi = w.sp.hi in
  let e = w.ending in
  if Interior.fades_light e && index_in w e >= 0 then begin
    let d = hi -. lo and fc = e.fade_color in
    Color.acc_set a
      (a.ar *. Interior.fade_channel e fc.r d)
      (a.ag *. Interior.fade_channel e fc.g d)
      (a.ab *. Interior.fade_channel e fc.b d)
  end;
  let inner = ref true in
  for j = 0 to w.ni - 1 do
    let i = w.inside.(j) in
    if not i.hollow then inner := false;
    (* the interior's media dim the light (POV-Ray 3.7 does so whatever
       the light's media_attenuation), but for the last stretch, from
       the last surface crossed to the light, where POV-Ray computes the
       atmosphere alone (trace.cpp's TraceShadowRay) *)
    if i.media <> [] && not w.last then Media.transmittance_into i.media r w.sp a
  done;
  if w.fogs != [] && !inner then begin
    Vec3.set w.fo (r.ox +. (lo *. r.dx)) (r.oy +. (lo *. r.dy)) (r.oz +. (lo *. r.dz));
    Vec3.set w.fd r.dx r.dy r.dz;
    Fog.dim w.fogs w.fo w.fd (hi -. lo) a
  end

(* the interiors of [l] not yet in the walk's set, added *)
let rec add_start (w : walk) = function
  | [] -> ()
  | (i : Interior.t) :: r ->
      if index_in w i < 0 then begin
        w.inside.(w.ni) <- i;
        w.ni <- w.ni + 1
      end;
      add_start w r

(* The recorded crossings taken in the order of distance, the stretches
   between them (and the ray's ends) dimmed by [stretch]. The ray starts
   in [w.start], the interiors of the ray whose hit it lights, and at
   each crossing leaves the crossed object's interior if it is in it,
   else enters it, as POV-Ray's shadow rays do (trace.cpp's
   ComputeShadowMedia): a merge of parts with their own interiors, or a
   solid left through a clipped-away hole, is not taken for what its
   geometry says. POV-Ray's fogs
   dim a media_attenuation light's shadow ray only where it runs outside
   solids (measured: 0.548806 = exp(-0.6), not exp(-0.65), with a clear
   solid box 1 unit deep on 10 units of fog of distance 20); the media of
   a hollow CSG only over the stretches inside it (measured: a shell
   between spheres of radius 10 and 20 with absorption 0.05, lit from a
   point inside it through one side: 0.606531 = exp(-0.5)). *)
let stretches (w : walk) =
  let dist = w.seg.len in
  let n = w.nf and ts = w.fts and ord = w.order in
  Floats.order_prefix ts n ord;
  w.ni <- 0;
  let need = n + List.length w.start in
  if Array.length w.inside < need then w.inside <- Array.make need Interior.default;
  add_start w w.start;
  let lo = ref 0. in
  for a = 0 to n do
    let hi = if a = n then dist else Float.Array.get ts ord.(a) in
    if hi > !lo && not (Color.acc_is_black w.acc) then begin
      w.sp.lo <- !lo;
      w.sp.hi <- hi;
      w.ending <- (if a = n then Interior.default else w.fobjs.(ord.(a)).interior);
      w.last <- a = n;
      stretch w
    end;
    if a < n then toggle w w.fobjs.(ord.(a)).interior;
    lo := Floats.fmax !lo hi
  done

(* POV-Ray's projected_through (trace.cpp, TracePointLightShadowRay):
   the light passes only when the shadow ray meets the object (its first
   crossing past 1e-4, POV-Ray's MIN_ISECT_DEPTH) before the light; then
   only what lies before that crossing (less 0.001, its SMALL_TOLERANCE)
   casts shadows, whence [w.ray.far]. From inside the object the ray's
   way out is such a crossing; a point on the object's own surface facing
   the light has none ahead. *)
let projected (w : walk) (o : Object.t) =
  let h = w.ph in
  h.t <- infinity;
  h.floor <- neg_infinity;
  Object.hit_s o w.ray 1e-4 h w.pf
  && h.t < w.seg.len
  && begin
       w.ray.far <- h.t -. 0.001;
       true
     end

(* Light reaching the origin of the walk's ray from [w.seg.len] along its
   unit direction: the product of (f*P + t) of every surface crossed, with
   interior fade over the lengths travelled inside fading objects; black
   when something opaque blocks (or, with projected_through, when the ray
   misses the object). Left in [w.acc]: stored in the walk's own fields,
   nothing is allocated or written through [caml_modify] unless a
   crossing lets light through. *)
let shadow_into (s : Scene.t) (w : walk) =
  let dist = w.seg.len in
  Color.acc_set w.acc 1. 1. 1.;
  w.nf <- 0;
  (* what lies within POV-Ray's shadow tolerance (1e-3) of the light casts
     no shadow: a light in a surface's plane (a Cornell box's ceiling
     lights) is not hidden by that surface, by rounding, at random *)
  w.ray.far <- dist -. Ray.shadow_epsilon;
  (* [w.seg.len], not [dist], to [projected]: a float passed is boxed *)
  let seen = match w.through with None -> true | Some o -> projected w o in
  if not seen then Color.acc_set w.acc 0. 0. 0.
  else if w.occlude then begin
    let visible = Scene.occluders_with s w.query w.ray Ray.shadow_epsilon shadow_opaque shadow_hit in
    if not visible then Color.acc_set w.acc 0. 0. 0.
    else begin
      if w.nf > 0 || w.fogs != [] then stretches w;
      (* atmospheric media: over the whole shadow ray, inside solids too
         (POV-Ray 3.7 does so, measured: a clear solid box on the way
         dims the light as much as a hollow one) *)
      if w.air <> [] then begin
        w.sp.lo <- 0.;
        w.sp.hi <- dist;
        Media.transmittance_into w.air w.ray w.sp w.acc
      end
    end
  end

(* Sample (i, j) of the area light in [w]: the shadow colour from its
   point, seen from [w.lp] (toward the sample, or, for a cylindrical or
   parallel light, along the line from its point_at through the sample,
   to the plane through the sample: POV-Ray's rule) *)
let area_sample (w : walk) i j (out : Color.acc) =
  let light = w.alight and a = w.aarea and p = w.lp and q = w.q and l = w.sl in
  Light.sample_on light a w.ax i j q;
  Light.direction_at light q.mx q.my q.mz p l;
  Ray.set w.ray p l.lx l.ly l.lz;
  w.seg.len <- l.dist;
  (match w.ascene with Some s -> shadow_into s w | None -> ());
  Color.acc_set out w.acc.ar w.acc.ag w.acc.ab

(* The shadow colour at [p] of a point light whose direction is in [w.l],
   into [w.acc] *)
(* POV-Ray dims shadow rays by atmospheric media only for lights with
   media_attenuation on *)
let[@inline] aim (s : Scene.t) (w : walk) (light : Light.t) =
  (let f = if light.media_attenuation && light.media_interaction then s.fog else [] in
   if w.fogs != f then w.fogs <- f);
  if w.through != light.projected_through then w.through <- light.projected_through;
  w.occlude <- not light.shadowless;
  (* read only where photons block shadow rays ({!collects}) *)
  if w.collecting && w.lphotons != light.photons then w.lphotons <- light.photons;
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
      Light.axes_into light a p w.ax;
      Light.average_area_into a w area_sample w.mean;
      let c = w.mean in
      Color.acc_set w.acc c.ar c.ag c.ab

let walk () = Scratch.get shadow_key
let rec any_media = function [] -> false | (i : Interior.t) :: r -> i.media <> [] || any_media r

(* set at every layer shaded: most often the same list (no interiors),
   left as it is then *)
let starts_in w l =
  if w.start != l then begin
    w.start <- l;
    w.start_media <- any_media l
  end
let[@inline] toward w = w.l
let[@inline] passed w = w.acc

let collects w b = w.collecting <- b
