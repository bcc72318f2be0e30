open Color

let light_min_cos = 1e-10

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
              filter_into (if j = 0 then pk.t0 else pk.t1) q sub (d + 1);
              let k = if j = 0 then pk.w.k0 else pk.w.k1 in
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

(* shadow rays fade only with a fade_power (povray 3.7: fade_power 0 fades
   what the eye sees through, by 1/2, but not the light) *)
let has_fade (i : Interior.t) = i.fade_distance <> 0. && i.fade_power <> 0.

(* The walk's state lives in a per-domain record, so that the callback is
   a closed function (no closure and refs per shadow ray); texture_filter
   traces nothing, so walks never nest on a domain. [ray] holds the
   shadow ray, [l] the direction to the light being shaded. *)
type length = { mutable len : float }

type shadow_walk = {
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
}

let shadow_key =
  Scratch.key (fun () ->
      { acc = Color.acc 1.; fobjs = [||]; fts = Float.Array.create 0; nf = 0;
        sorted = Float.Array.create 0; inside_f = Object.found (Object.make (Shape.sphere Vec3.zero 1.));
        ray = Ray.scratch (); l = Light.dir (); seg = { len = 0. };
        alight = Light.point Vec3.zero Color.black; aarea = Light.area Vec3.unit_x Vec3.unit_z 1 1;
        ascene = None; lp = Vec3.m (); q = Vec3.m (); mean = Color.acc 0.; cross = Vec3.m ();
        filter = Color.acc 0. })

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
    Color.acc_set a (a.ar *. f.ar) (a.ag *. f.ag) (a.ab *. f.ab);
    if has_fade o.interior then add_fader w o h;
    not (Color.acc_is_black a)
  end

(* where [shadow_hit] is false whatever the crossing *)
let shadow_opaque (o : Object.t) = Texture.blocks_light o.texture

(* Each object crossed, taken last crossed first: the segments between
   its crossings (and the ray's ends) whose middle is inside it fade what
   passes. Distances of one object sorted in place. *)
let fade_segments (w : shadow_walk) dist =
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
            Color.acc_set a
              (a.ar *. Interior.fade_channel inner fc.r d)
              (a.ag *. Interior.fade_channel inner fc.g d)
              (a.ab *. Interior.fade_channel inner fc.b d)
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
let shadow_into (s : Scene.t) (w : shadow_walk) =
  let dist = w.seg.len in
  Color.acc_set w.acc 1. 1. 1.;
  w.nf <- 0;
  w.ray.far <- dist;
  let visible = Scene.occluders_s s w.ray Ray.shadow_epsilon shadow_opaque shadow_hit in
  if not visible then Color.acc_set w.acc 0. 0. 0. else if w.nf > 0 then fade_segments w dist

(* Sample (i, j) of the area light in [w]: the shadow colour from its
   point, seen from [w.lp] *)
let area_sample (w : shadow_walk) i j (out : Color.acc) =
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
let point_shadow s (w : shadow_walk) (p : Vec3.m) =
  let l = w.l in
  Ray.set w.ray p l.lx l.ly l.lz;
  w.seg.len <- l.dist;
  shadow_into s w

(* Shadow colour of one light at [p], whose direction is in [w.l], into
   [w.acc]: area lights average their samples. *)
let light_shadow s (w : shadow_walk) (light : Light.t) (p : Vec3.m) =
  match light.area with
  | None -> point_shadow s w p
  | Some a ->
      if w.alight != light then w.alight <- light;
      if w.aarea != a then w.aarea <- a;
      (match w.ascene with Some s' when s' == s -> () | _ -> w.ascene <- Some s);
      Vec3.set w.lp p.mx p.my p.mz;
      Light.average_area_into a w area_sample w.mean;
      let c = w.mean in
      Color.acc_set w.acc c.ar c.ag c.ab

(* POV-Ray's approximate metallic Fresnel term, x = angle / 90 degrees. *)
(* [m] > 0: the tint is 1 + k (c - 1) per channel c of the pigment, k
   as follows; [m] = 0: no tint (1) *)
let[@inline] metallic_k m cos_angle =
  let x = Float.acos (Float.min 1. (Float.abs cos_angle)) /. (Float.pi /. 2.) in
  let f = (0.014567225 /. ((x -. 1.12) ** 2.)) -. 0.011612903 in
  let f = Float.min 1. (Float.max 0. f) in
  m *. (1. -. f)

let[@inline] tint m k c = if m = 0. then 1. else 1. +. (k *. (c -. 1.))

let fresnel n c =
  let g2 = (n *. n) +. (c *. c) -. 1. in
  if g2 <= 0. then 1.
  else
    let g = Float.sqrt g2 in
    let a = (g -. c) /. (g +. c) and b = ((c *. (g +. c)) -. 1.) /. ((c *. (g -. c)) +. 1.) in
    0.5 *. a *. a *. (1. +. (b *. b))

(* [Vec3.dot], in place: the same arithmetic *)
let dot = Vec3.dot_m

(* A nesting level's scalars, stored flat, so that passing them
   allocates nothing: the relative index, the current layer's opacity,
   the level's ADC weight, the weight of a reflection being traced
   ([refl]) and of the ray traced next from here ([child], read by
   [trace_ray] as it starts). *)
type nums = {
  mutable eta : float;
  mutable alpha : float;
  mutable weight : float;
  mutable refl : float;
  mutable child : float;
}

let nums () = { eta = 1.; alpha = 1.; weight = 1.; refl = 1.; child = 1. }

(* Diffuse and highlights of one light seen from [p], added into [out];
   the shadow is [light_shadow] (an area light's samples come here as
   point lights). Scalars throughout: nothing is allocated unless the
   shadow ray crosses something transparent. [k.alpha]: the layer's
   opacity. *)
let one_light s (f : Finish.t) (pc : Pigment.out) (k : nums) (p : Vec3.m) (n : Vec3.m) (d : Vec3.m)
    (light : Light.t) (lp : Vec3.m) sampled (out : Color.acc) =
  let alpha = k.alpha in
  let w = Scratch.get shadow_key in
  let l = w.l in
  (* [sampled]: a sample of an area light at [lp], as a point light *)
  if sampled then Light.direction_at light lp.mx lp.my lp.mz p l else Light.direction_into light p l;
  let nl = (n.mx *. l.lx) +. (n.my *. l.ly) +. (n.mz *. l.lz) in
  let front = nl >= light_min_cos in
  let back = (not front) && f.diffuse_back > 0. && -.nl >= light_min_cos in
  let att =
    if not (front || back) then 0.
    else if sampled then Light.attenuation_at light lp.mx lp.my lp.mz p
    else Light.attenuation_m light p
  in
  if att > 0. then begin
    let lr = att *. light.color.r and lg = att *. light.color.g and lb = att *. light.color.b in
    (* no tuple: the channels stay unboxed *)
    if not light.shadowless then if sampled then point_shadow s w p else light_shadow s w light p;
    let sh = w.acc in
    let lr = if light.shadowless then lr else lr *. sh.ar
    and lg = if light.shadowless then lg else lg *. sh.ag
    and lb = if light.shadowless then lb else lb *. sh.ab in
    if not (lr = 0. && lg = 0. && lb = 0.) then
      if back then begin
        let k = alpha *. f.diffuse_back *. Float.pow (-.nl) f.brilliance in
        out.ar <- out.ar +. (k *. (pc.r *. lr));
        out.ag <- out.ag +. (k *. (pc.g *. lg));
        out.ab <- out.ab +. (k *. (pc.b *. lb))
      end
      else begin
        let cr = ref 0. and cg = ref 0. and cb = ref 0. in
        if f.diffuse > 0. then begin
          let k = alpha *. f.diffuse *. (if f.brilliance = 1. then nl else Float.pow nl f.brilliance) in
          cr := !cr +. (k *. (pc.r *. lr));
          cg := !cg +. (k *. (pc.g *. lg));
          cb := !cb +. (k *. (pc.b *. lb))
        end;
        if not light.shadowless then begin
          let m = f.metallic in
          let mk = if m = 0. then 0. else metallic_k m nl in
          let mr = lr *. tint m mk pc.r and mg = lg *. tint m mk pc.g and mb = lb *. tint m mk pc.b in
          if f.phong > 0. then begin
            (* r = d - 2 (d.n) n, the mirror direction *)
            let k = -2. *. dot d n in
            let rx = d.mx +. (k *. n.mx) and ry = d.my +. (k *. n.my) and rz = d.mz +. (k *. n.mz) in
            let rl = (rx *. l.lx) +. (ry *. l.ly) +. (rz *. l.lz) in
            if rl > 0. then begin
              let k = f.phong *. Float.pow rl f.phong_size in
              cr := !cr +. (k *. mr);
              cg := !cg +. (k *. mg);
              cb := !cb +. (k *. mb)
            end
          end;
          if f.specular > 0. then begin
            (* h = (l - d) / |l - d|, the half vector *)
            let hx = l.lx -. d.mx and hy = l.ly -. d.my and hz = l.lz -. d.mz in
            let len = Float.sqrt ((hx *. hx) +. (hy *. hy) +. (hz *. hz)) in
            let k = if len > 0. then 1. /. len else 1. in
            let nh = (n.mx *. (k *. hx)) +. (n.my *. (k *. hy)) +. (n.mz *. (k *. hz)) in
            if nh > 0. then begin
              let k = f.specular *. Float.pow nh (1. /. f.roughness) in
              cr := !cr +. (k *. mr);
              cg := !cg +. (k *. mg);
              cb := !cb +. (k *. mb)
            end
          end
        end;
        out.ar <- out.ar +. !cr;
        out.ag <- out.ag +. !cg;
        out.ab <- out.ab +. !cb
      end
  end

(* the sum of [direct], per domain: nothing in it traces *)
let direct_key = Scratch.key (fun () -> Color.acc 0.)

(* Per domain: what an area light that shades per sample
   (area_illumination) needs for each: the scene, the light, the shaded
   point's finish, pigment, numbers, point, normal and ray, a sample's
   position *)
type illum = {
  mutable iscene : Scene.t option;
  mutable ilight : Light.t;
  mutable iarea : Light.area;
  mutable ifinish : Finish.t;
  mutable ipc : Pigment.out;
  mutable ik : nums;
  mutable ip : Vec3.m;
  mutable inn : Vec3.m;
  mutable id : Vec3.m;
  ipos : Vec3.m;
  isum : Color.acc;
}

let illum_key =
  Scratch.key (fun () ->
      { iscene = None; ilight = Light.point Vec3.zero Color.black;
        iarea = Light.area Vec3.unit_x Vec3.unit_z 1 1; ifinish = Finish.default; ipc = Pigment.out ();
        ik = nums (); ip = Vec3.m (); inn = Vec3.m (); id = Vec3.m (); ipos = Vec3.m (); isum = Color.acc 0. })

(* sample (i, j) of the area light in [il] shading as a point light there *)
let illum_sample (il : illum) i j (o : Color.acc) =
  let light = il.ilight and a = il.iarea in
  Light.position_into light a il.ip (Light.offset a.n1 i) (Light.offset a.n2 j) il.ipos;
  Color.acc_set o 0. 0. 0.;
  match il.iscene with
  | Some s -> one_light s il.ifinish il.ipc il.ik il.ip il.inn il.id light il.ipos true o
  | None -> ()

(* Diffuse and highlights of every light for one texture layer, added
   into [out]. *)
(* [one_light]'s position when the light is where it stands (unread) *)
let own_position = Vec3.m ()

let[@inline] direct (s : Scene.t) (f : Finish.t) (pc : Pigment.out) (k : nums) p n d out =
  for j = 0 to Array.length s.lights - 1 do
    let light = Array.unsafe_get s.lights j in
    match light.area with
    | Some a when a.area_illumination ->
        (* every sample shades as a point light; averaged like shadows *)
        let il = Scratch.get illum_key in
        (match il.iscene with Some s' when s' == s -> () | _ -> il.iscene <- Some s);
        il.ilight <- light;
        il.iarea <- a;
        il.ifinish <- f;
        il.ipc <- pc;
        il.ik <- k;
        il.ip <- p;
        il.inn <- n;
        il.id <- d;
        let c = il.isum in
        Light.average_area_into a il illum_sample c;
        out.ar <- out.ar +. c.ar;
        out.ag <- out.ag +. c.ag;
        out.ab <- out.ab +. c.ab
    | _ -> one_light s f pc k p n d light own_position false out
  done

(* Heckbert's k < 0: no refracted ray at this relative index and cosine *)
let[@inline] total_internal eta cos_i = eta > 1. && 1. +. (eta *. eta *. ((cos_i *. cos_i) -. 1.)) < 0.

(* What shading one hit keeps, one frame per nesting level, per domain,
   reused from ray to ray ([trace_camera_ray] starts every camera ray at depth
   0): the running sums; the hit point, the normal facing the ray, the
   top layer's normal once known ([top_set]) and a perturbed normal; the
   direction of a ray traced from here and what it brings back; the
   scalars. The frame stays taken while rays traced from it run (they
   read its point and direction): nothing is allocated per hit. *)
type frame = {
  c : Color.acc;
  tr : Color.acc;
  rf : Color.acc;
  p : Vec3.m;
  n0 : Vec3.m;
  top : Vec3.m;
  mutable top_set : bool;
  pn : Vec3.m;
  rd : Vec3.m;
  rc : Color.acc;
  k : nums;
  pig : Pigment.out;  (** the pigment of the layer being shaded *)
  fade : Color.acc;  (** the fade of the medium the ray came through *)
}

let new_frame () =
  { c = Color.acc 0.; tr = Color.acc 1.; rf = Color.acc 0.; p = Vec3.m (); n0 = Vec3.m ();
    top = Vec3.m (); top_set = false; pn = Vec3.m (); rd = Vec3.m (); rc = Color.acc 0.;
    k = nums (); pig = Pigment.out (); fade = Color.acc 1. }

let frames_key = Scratch.key (fun () -> Scratch.levels ~initial:8 new_frame)

let enter () =
  let f = Scratch.push (Scratch.get frames_key) in
  Color.acc_set f.c 0. 0. 0.;
  Color.acc_set f.tr 1. 1. 1.;
  f.top_set <- false;
  f

let leave () = Scratch.pop (Scratch.get frames_key)

(* The same for texture maps being blended (nested in one another, or in
   what the rays of their textures' reflections meet): the textures
   picked, their sum, and the one being shaded. *)
type tmap_level = { pick : Texture.pick; c : Color.acc; f : Color.acc; c1 : Color.acc; f1 : Color.acc }

let tmaps_key =
  Scratch.key (fun () ->
      Scratch.levels (fun () ->
          { pick = Texture.pick (); c = Color.acc 0.; f = Color.acc 0.; c1 = Color.acc 0.; f1 = Color.acc 1. }))

let tmap_enter () = Scratch.push (Scratch.get tmaps_key)
let tmap_leave () = Scratch.pop (Scratch.get tmaps_key)

(* Relative index of refraction across a surface of [inner] for a ray
   inside [media]: entering or leaving is decided as POV-Ray does, by
   whether the ray is already inside this interior, not by the side of
   the surface (the children of a CSG share their parent's interior, so in
   the overlap of a union of glass spheres the inner walls bend light as
   glass/air). [media] holds each interior once. *)
let rec ior_beyond (inner : Interior.t) = function
  | (i : Interior.t) :: r -> if i == inner then ior_beyond inner r else i.ior
  | [] -> 1.

(* no local function: so that it inlines, and its result is not boxed *)
let[@inline] relative_ior (inner : Interior.t) media =
  if not (List.memq inner media) then
    (match media with (i : Interior.t) :: _ -> i.ior | [] -> 1.) /. inner.ior
  else inner.ior /. ior_beyond inner media

(* Lists of media entered, made once per domain: [inner :: media] for
   the last pairs met (a ray entering glass would otherwise make a list
   cell at every refraction) *)
let entered_size = 16

type entered = {
  inners : Interior.t array;
  outers : Interior.t list array;
  lists : Interior.t list array;
  mutable filled : int;
  mutable next : int;
}

let entered_key =
  Scratch.key (fun () ->
      { inners = Array.make entered_size Interior.default; outers = Array.make entered_size [];
        lists = Array.make entered_size []; filled = 0; next = 0 })

let enter_medium (inner : Interior.t) media =
  let e = Scratch.get entered_key in
  let i = ref 0 in
  while !i < e.filled && not (Array.unsafe_get e.inners !i == inner && Array.unsafe_get e.outers !i == media) do
    incr i
  done;
  if !i < e.filled then Array.unsafe_get e.lists !i
  else begin
    let l = inner :: media and k = e.next in
    e.inners.(k) <- inner;
    e.outers.(k) <- media;
    e.lists.(k) <- l;
    e.next <- (k + 1) mod entered_size;
    if e.filled < entered_size then e.filled <- e.filled + 1;
    l
  end

(* the media beyond that surface *)
let next_media (inner : Interior.t) media =
  if not (List.memq inner media) then enter_medium inner media
  else match media with i :: r when i == inner -> r | m -> List.filter (fun i -> i != inner) m

let[@inline] set_color (out : Color.acc) (c : Color.t) = Color.acc_set out c.r c.g c.b

(* a ray's direction made unit, to look up the sky (per domain) *)
let sky_key = Scratch.key Vec3.m

(* a surface's own light [c] and, through it ([tr], faded), the light [rc]
   from beyond *)
let[@inline] through (out : Color.acc) (c : Color.acc) (tr : Color.acc) (fade : Color.acc) (rc : Color.acc) =
  Color.acc_set out
    (c.ar +. ((tr.ar *. fade.ar) *. rc.ar))
    (c.ag +. ((tr.ag *. fade.ag) *. rc.ag))
    (c.ab +. ((tr.ab *. fade.ab) *. rc.ab))

(* The ray from [o] along [d], hits beyond [tmin], its radiance into
   [out]; its ADC weight is [from.child]; [media]: the interiors the ray
   is inside, innermost first. [o] and [d] belong to the caller and are
   not written. *)
let rec trace_ray (s : Scene.t) tmin (o : Vec3.m) (d : Vec3.m) level (from : nums) media (out : Color.acc) =
  let weight = from.child in
  if level > s.settings.max_trace_level || weight < s.settings.adc_bailout then Color.acc_set out 0. 0. 0.
  else
    (* read at once, before shading traces anything else *)
    let h, f = Scene.hit_records () in
    if not (Scene.intersect_into s o d tmin infinity h f) then
      if Sky.is_empty s.sky then set_color out s.background
      else begin
        let u = Scratch.get sky_key in
        Vec3.set u d.mx d.my d.mz;
        Vec3.normalize_m u;
        Sky.eval_into s.sky ~background:s.background u out
      end
    else begin
      let t = h.t and obj = f.leaf in
      let fr = enter () in
      let p = fr.p in
      Vec3.set p (o.mx +. (t *. d.mx)) (o.my +. (t *. d.my)) (o.mz +. (t *. d.mz));
      Scene.hit_normal_into s f h p fr.n0;
      (* POV-Ray fades what comes through the far side of a medium, not
         the far surface's own shading *)
      let fade = fr.fade in
      (match media with
      | (i : Interior.t) :: _ when i.fade_distance <> 0. ->
          let c = i.fade_color in
          Color.acc_set fade (Interior.fade_channel i c.r t) (Interior.fade_channel i c.g t) (Interior.fade_channel i c.b t)
      | _ -> Color.acc_set fade 1. 1. 1.);
      fr.k.weight <- weight;
      shade s d obj fr level media fade out;
      leave ()
    end

(* [fr.n0] holds the surface's normal, turned to face the ray here;
   [fr.k.weight] the ray's weight *)
and shade s (d : Vec3.m) (obj : Object.t) fr level media (fade : Color.acc) (out : Color.acc) =
  let weight = fr.k.weight in
  let n0 = fr.n0 in
  let entering = dot n0 d < 0. in
  if not entering then Vec3.set n0 (-.n0.mx) (-.n0.my) (-.n0.mz);
  let inner = obj.interior in
  let eta = relative_ior inner media in
  fr.k.eta <- eta;
  let bailout = s.settings.adc_bailout in
  (* guessed from the unperturbed normal; shaded again in the rare case
     the top layer's normal or an opaque texture says otherwise *)
  let guess = total_internal eta (-.dot d n0) in
  let c = fr.c and tr = fr.tr in
  layers s d level media fr (not guess) c tr obj.texture;
  let n = if fr.top_set then fr.top else n0 in
  if guess <> (Color.acc_luminance tr > bailout && total_internal eta (-.dot d n)) then begin
    fr.top_set <- false;
    Color.acc_set c 0. 0. 0.;
    Color.acc_set tr 1. 1. 1.;
    layers s d level media fr guess c tr obj.texture
  end;
  if Color.acc_luminance tr <= bailout then Color.acc_set out c.ar c.ag c.ab
  else
    let w = weight *. Color.acc_max tr in
    let rc = fr.rc in
    if eta = 1. then begin
      (* same index on both sides: straight through, no trace level used *)
      fr.k.child <- w;
      trace_ray s Ray.epsilon fr.p d level fr.k (next_media inner media) rc;
      through out c tr fade rc
    end
    else
      let cos_i = -.dot d n in
      let k = 1. +. (eta *. eta *. ((cos_i *. cos_i) -. 1.)) in
      let rd = fr.rd in
      if k < 0. then begin
        (* total internal reflection: not filtered by the surface colour *)
        let m = 2. *. cos_i in
        Vec3.set rd (d.mx +. (m *. n.mx)) (d.my +. (m *. n.my)) (d.mz +. (m *. n.mz));
        fr.k.child <- weight;
        trace_ray s Ray.epsilon fr.p rd (level + 1) fr.k media rc;
        Color.acc_set out (c.ar +. (fade.ar *. rc.ar)) (c.ag +. (fade.ag *. rc.ag)) (c.ab +. (fade.ab *. rc.ab))
      end
      else begin
        let m = (eta *. cos_i) -. Float.sqrt k in
        Vec3.set rd ((eta *. d.mx) +. (m *. n.mx)) ((eta *. d.my) +. (m *. n.my)) ((eta *. d.mz) +. (m *. n.mz));
        fr.k.child <- w;
        trace_ray s Ray.epsilon fr.p rd (level + 1) fr.k (next_media inner media) rc;
        through out c tr fade rc
      end

(* Shade the layers of a texture top down, adding into [acc]; [w] is what
   the layers above let through, and holds at the end what the whole
   texture lets through; sets the frame's top normal to the top layer's.
   [refl]: add the finishes' reflection (POV-Ray leaves it out where the
   light passing through is totally reflected inside: the TIR ray stands
   for it). A function of its own, not a closure in [shade]: it runs for
   every hit. *)
and layers s d level media (fr : frame) refl (acc : Color.acc) (w : Color.acc) = function
  | [] -> ()
  | (layer : Texture.layer) :: rest -> (
      match layer.tmap with
      | Some m ->
          (* a patterned layer: blend the textures around the value *)
          let lv = tmap_enter () in
          let pk = lv.pick and c = lv.c and f = lv.f in
          Texture.blend_m m fr.p pk;
          Color.acc_set c 0. 0. 0.;
          Color.acc_set f 0. 0. 0.;
          for j = 0 to pk.n - 1 do
            let c' = lv.c1 and f' = lv.f1 in
            Color.acc_set c' 0. 0. 0.;
            Color.acc_set f' 1. 1. 1.;
            layers s d level media fr refl c' f' (if j = 0 then pk.t0 else pk.t1);
            let k = if j = 0 then pk.w.k0 else pk.w.k1 in
            Color.acc_set c (c.ar +. (k *. c'.ar)) (c.ag +. (k *. c'.ag)) (c.ab +. (k *. c'.ab));
            Color.acc_set f (f.ar +. (k *. f'.ar)) (f.ag +. (k *. f'.ag)) (f.ab +. (k *. f'.ab))
          done;
          Color.acc_set acc (acc.ar +. (w.ar *. c.ar)) (acc.ag +. (w.ag *. c.ag)) (acc.ab +. (w.ab *. c.ab));
          Color.acc_set w (w.ar *. f.ar) (w.ag *. f.ag) (w.ab *. f.ab);
          tmap_leave ();
          if not (Color.acc_is_black w) then layers s d level media fr refl acc w rest
      | None ->
          let p = fr.p and n0 = fr.n0 in
          let n =
            match layer.normal with
            | None -> n0
            | Some nm ->
                (* a normal tilted away from the eye is mirrored back *)
                let pn = fr.pn in
                Normal.perturb_m nm p n0 pn;
                let md = dot pn d in
                if md > 0. then begin
                  let k = -2. *. md in
                  Vec3.set pn (pn.mx +. (k *. d.mx)) (pn.my +. (k *. d.my)) (pn.mz +. (k *. d.mz));
                  Vec3.normalize_m pn
                end;
                pn
          in
          if not fr.top_set then begin
            fr.top_set <- true;
            Vec3.set fr.top n.mx n.my n.mz
          end;
          let f = layer.finish in
          let pig = fr.pig in
          Pigment.into layer.pigment p pig;
          let pc = pig in
          let k = fr.k in
          k.alpha <-
            (if s.Scene.settings.legacy_alpha then
               1. -. ((pig.filter *. Float.max pc.r (Float.max pc.g pc.b)) +. pig.transmit)
             else 1. -. pig.filter -. pig.transmit);
          let alpha = k.alpha in
          (* this layer's own colour: lights, then ambient and emission *)
          let dl = Scratch.get direct_key in
          Color.acc_set dl 0. 0. 0.;
          direct s f pc k p n d dl;
          let amb = s.settings.ambient_light in
          let lr = dl.ar +. (alpha *. (pc.r *. ((f.ambient.r *. amb.r) +. f.emission.r)))
          and lg = dl.ag +. (alpha *. (pc.g *. ((f.ambient.g *. amb.g) +. f.emission.g)))
          and lb = dl.ab +. (alpha *. (pc.b *. ((f.ambient.b *. amb.b) +. f.emission.b))) in
          (* no tuple: the channels stay unboxed *)
          let refl_here = refl && Finish.has_reflection f in
          let rc = fr.rf in
          if refl_here then begin
            k.refl <- k.weight *. Color.acc_max w;
            reflection s f pc n d level media fr rc
          end;
          let lr = if refl_here then lr +. rc.ar else lr
          and lg = if refl_here then lg +. rc.ag else lg
          and lb = if refl_here then lb +. rc.ab else lb in
          Color.acc_set acc (acc.ar +. (w.ar *. lr)) (acc.ag +. (w.ag *. lg)) (acc.ab +. (w.ab *. lb));
          Color.acc_set w
            (w.ar *. ((pig.filter *. pc.r) +. pig.transmit))
            (w.ag *. ((pig.filter *. pc.g) +. pig.transmit))
            (w.ab *. ((pig.filter *. pc.b) +. pig.transmit));
          if not (Color.acc_is_black w) then layers s d level media fr refl acc w rest)

(* the reflected light into [out] (the frame's [rf]); the reflected ray
   starts at the frame's point along its [rd], weighs [fr.k.refl] times
   the reflection's, and brings its light back into its [rc] *)
and reflection s (f : Finish.t) (pc : Pigment.out) (n : Vec3.m) (d : Vec3.m) level media (fr : frame) (out : Color.acc) =
  if not (Finish.has_reflection f) then Color.acc_set out 0. 0. 0.
  else
    let rf = f.reflection in
    let eta = fr.k.eta in
    let cos_i = -.dot d n in
    (* kr = rmin + k (rmax - rmin), per channel, in scalars *)
    let lo = rf.rmin and hi = rf.rmax in
    let k =
      if rf.fresnel then if eta = 1. then 0. else fresnel (1. /. eta) cos_i
      else Float.pow (1. -. cos_i) rf.falloff
    in
    let kr = lo.r +. (k *. (hi.r +. (-1. *. lo.r)))
    and kg = lo.g +. (k *. (hi.g +. (-1. *. lo.g)))
    and kb = lo.b +. (k *. (hi.b +. (-1. *. lo.b))) in
    let w =
      if rf.fresnel then Float.max kr (Float.max kg kb)
      else Float.max (max_channel lo) (max_channel hi)
    in
    let m = rf.rmetallic in
    let mk = if m = 0. then 0. else metallic_k m cos_i in
    let kr = kr *. tint m mk pc.r and kg = kg *. tint m mk pc.g and kb = kb *. tint m mk pc.b in
    if kr = 0. && kg = 0. && kb = 0. then Color.acc_set out 0. 0. 0.
    else begin
      let m = 2. *. cos_i in
      let rd = fr.rd and rc = fr.rc in
      Vec3.set rd (d.mx +. (m *. n.mx)) (d.my +. (m *. n.my)) (d.mz +. (m *. n.mz));
      fr.k.child <- fr.k.refl *. w;
      trace_ray s Ray.epsilon fr.p rd (level + 1) fr.k media rc;
      if rf.exponent = 1. then Color.acc_set out (kr *. rc.ar) (kg *. rc.ag) (kb *. rc.ab)
      else
        let e = 1. /. rf.exponent in
        Color.acc_set out (kr *. Float.pow rc.ar e) (kg *. Float.pow rc.ag e) (kb *. Float.pow rc.ab e)
    end

(* POV-Ray starts camera rays inside every object that contains the
   camera (the last one in the scene first). Cached per scene and origin:
   the camera location is the same for every ray of a pinhole camera. *)
type start = {
  mutable scene : Scene.t option;
  at : Vec3.m;
  mutable media : Interior.t list;
  now : Scene.objects;  (** the objects holding [at] *)
  held : Scene.objects;  (** those [media] was made from *)
}

let start_key =
  Scratch.key (fun () ->
      { scene = None; at = Vec3.m (); media = []; now = Scene.objects (); held = Scene.objects () })


(* per domain: a cache shared by domains would be written from both when
   the origin changes at every ray (orthographic camera, focal blur); a
   new origin costs an allocation only where some object holds it *)
let start_media (s : Scene.t) (o : Vec3.m) =
  let c = Scratch.get start_key in
  let at = c.at in
  match c.scene with
  | Some s' when s' == s && at.mx = o.mx && at.my = o.my && at.mz = o.mz -> c.media
  | _ ->
      let same_scene = match c.scene with Some s' -> s' == s | None -> false in
      if not same_scene then c.scene <- Some s;
      Vec3.set at o.mx o.my o.mz;
      Scene.containing_into s o c.now;
      (* a new origin held by the same objects (lens rays, an
         orthographic camera): the same list *)
      if same_scene && Scene.same_objects c.now c.held then c.media
      else begin
        let now = c.now and held = c.held in
        let m = List.init now.n (fun i -> (now.items.(i) : Object.t).interior) in
        held.n <- 0;
        for i = 0 to now.n - 1 do
          Scene.add_object held now.items.(i)
        done;
        c.media <- m;
        m
      end

(* A camera ray, per domain: its origin and direction, and its light. *)
type camera_ray = {
  o : Vec3.m;
  d : Vec3.m;
  light : Color.acc;
  k : nums;  (** [child] 1 *)
  at : Vec3.m;  (** an image point (x, y) being sampled by a lens *)
  cam : Vec3.m;  (** its coordinates on the camera (x, y) *)
}

let camera_key =
  Scratch.key (fun () -> { o = Vec3.m (); d = Vec3.m (); light = Color.acc 0.; k = nums (); at = Vec3.m (); cam = Vec3.m () })

(* the radiance along [r] into [out] *)
let trace_camera_ray s (r : camera_ray) out =
  Scratch.reset (Scratch.get frames_key);
  trace_ray s 0. r.o r.d 1 r.k (start_media s r.o) out

let trace s (ray : Ray.t) =
  let r = Scratch.get camera_key in
  Vec3.load r.o ray.origin;
  Vec3.load r.d ray.dir;
  trace_camera_ray s r r.light;
  Color.of_acc r.light

(* Focal blur (camera aperture > 0): the mean of [blur_samples] rays
   through points of the lens, stratified by a Hammersley set turned by
   a per-pixel offset (POV-Ray picks its lens points at random and stops
   early by a confidence test, so blurred parts agree in the mean, not
   pixel for pixel). *)
let[@inline] radical_inverse k =
  let k = ref k and f = ref 0.5 and acc = ref 0. in
  while !k <> 0 do
    if !k land 1 = 1 then acc := !acc +. !f;
    f := !f *. 0.5;
    k := !k lsr 1
  done;
  !acc

(* per domain: the lens points' sampler and the sum of their light *)
let blur_key = Scratch.key (fun () -> (Sampler.create ~seed:0 ~pixel:0 ~sample:0, Color.acc 0.))

(* for the image point in [r.at] (its camera coordinates in [r.cam]): read
   from the record, the four coordinates passed would be boxed *)
let focal_blur_into (s : Scene.t) (r : camera_ray) out =
  let px = r.at.mx and py = r.at.my and sx = r.cam.mx and sy = r.cam.my in
  let cam = s.camera in
  let n = if cam.blur_samples > 0 then cam.blur_samples else 10 (* camlray's default *) in
  let key = (int_of_float (Float.floor py) * 65599) + int_of_float (Float.floor px) in
  let sampler, sum = Scratch.get blur_key in
  Sampler.reset sampler ~seed:0 ~pixel:key ~sample:0;
  let du = Sampler.get sampler 0 and dv = Sampler.get sampler 1 in
  Color.acc_set sum 0. 0. 0.;
  for k = 0 to n - 1 do
    let u = Float.rem (((float_of_int k +. 0.5) /. float_of_int n) +. du) 1. in
    let v = Float.rem (radical_inverse k +. dv) 1. in
    Camera.lens_into cam sx sy u v r.o r.d;
    trace_camera_ray s r r.light;
    let l = r.light in
    Color.acc_set sum (sum.ar +. l.ar) (sum.ag +. l.ag) (sum.ab +. l.ab)
  done;
  let k = 1. /. float_of_int n in
  Color.acc_set out (k *. sum.ar) (k *. sum.ag) (k *. sum.ab)

(* The light through the image point [(px, py)] into [out]; inlined:
   the coordinates stay unboxed. *)
let[@inline] sample_in (s : Scene.t) ~width ~height px py out =
  let sx = Camera.pixel_x ~width px and sy = Camera.pixel_y ~height py in
  let cam = s.camera in
  let r = Scratch.get camera_key in
  if cam.aperture > 0. then begin
    Vec3.set r.at px py 0.;
    Vec3.set r.cam sx sy 0.;
    focal_blur_into s r out
  end
  else begin
    Camera.ray_into cam sx sy r.o r.d;
    trace_camera_ray s r out
  end

let sample_into s ~width ~height px py out = sample_in s ~width ~height px py out

let sample s ~width ~height px py =
  let out = Color.acc 0. in
  sample_in s ~width ~height px py out;
  Color.of_acc out

let pixel_into s ~width ~height x y out =
  sample_in s ~width ~height (float_of_int x +. 0.5) (float_of_int y +. 0.5) out

let pixel s ~width ~height x y =
  let out = Color.acc 0. in
  pixel_into s ~width ~height x y out;
  Color.of_acc out
