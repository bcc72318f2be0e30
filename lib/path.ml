open Color

(* if-based min/max: Float.min/max order NaN and -0 through a C call *)
let fmin = Floats.fmin
let fmax = Floats.fmax

type t = {
  scene : Scene.t;
  emitters : Emitter.t array;
  nee : bool;
  has_env : bool;
  volumes : bool;  (** fog, atmospheric or interior media: paths track the interiors they run in *)
  fogs : Fog.t list;
  air : Media.t list;  (** the atmosphere's media *)
  rainbows : Rainbow.t list;  (** those drawn *)
}

let prepare ?(nee = true) ?(extra = []) (scene : Scene.t) =
  let air = match scene.atmosphere with [] -> [] | (i : Interior.t) :: _ -> i.media in
  let fogs = List.filter (fun (f : Fog.t) -> Float.abs f.distance > 1e-10) scene.fog in
  let rainbows = List.filter Rainbow.drawn scene.rainbows in
  { scene; emitters = Array.append (Emitter.of_scene scene) (Array.of_list extra); nee;
    has_env = not (Sky.is_empty scene.sky && is_black scene.background);
    volumes =
      fogs <> [] || air <> [] || rainbows <> []
      || Array.exists (fun (o : Object.t) -> o.interior.media <> []) scene.objects;
    fogs; air; rainbows }

let[@inline] power a b =
  let a2 = a *. a and b2 = b *. b in
  if a2 +. b2 = 0. then 0. else a2 /. (a2 +. b2)

(* The state of a sample, per domain, in flat records: the ray, the
   vertex, the path's throughput and light, the material, the sampled
   directions. A path is walked in a loop over these, allocating nothing
   in the common case (solid pigments, point lights or the background,
   shapes of any kind). *)
type nums = { mutable prev_pdf : float }

let camera_v = 0 and specular_v = 1 and smooth_v = 2 and medium_v = 3

type state = {
  o : Vec3.m;  (** the ray *)
  d : Vec3.m;
  p : Vec3.m;  (** the vertex *)
  ng : Vec3.m;  (** the surface's normal there *)
  n : Vec3.m;  (** ... facing the ray *)
  wo : Vec3.m;
  thr : Color.acc;  (** throughput *)
  acc : Color.acc;  (** light found *)
  dl : Color.acc;  (** direct light at the vertex *)
  f : Color.acc;  (** f at a light's direction *)
  tr : Color.acc;  (** transmittance of a shadow ray *)
  sum : Color.acc;  (** a pixel's samples *)
  env_wi : Vec3.m;
  q : Vec3.m;  (** a shadow ray's crossing *)
  uv : Vec3.m;  (** a uv-mapped surface's uv (the vertex's, or a crossing's) *)
  pig : Pigment.out;  (** the pigment there *)
  env : Color.acc;  (** the environment's light along a direction *)
  prev_p : Vec3.m;  (** the previous vertex, when [prev] is [smooth_v] *)
  prev_n : Vec3.m;
  num : nums;
  mutable prev : int;
  mat : Material.lobes;
  bs : Bsdf.sampled;
  ls : Emitter.sampled;
  h : Hit.t;
  fd : Object.found;
  eh : Hit.t;  (** what a sample of a glowing sphere meets first *)
  efd : Object.found;
  le : Color.acc;  (** the light it sends *)
  shadow : Ray.scratch;
  sampler : Sampler.t;
  mutable set : Light.t array;  (** the lights of the vertex's surface (its light set) *)
  ph : Hit.t;  (** a shadow ray's crossing of a light's projected_through object *)
  pf : Object.found;
  mutable inside : Interior.t list;  (** the interiors the ray runs in (with {!t.volumes}) *)
  mutable sstart : Interior.t list;  (** those a shadow ray starts in *)
  mutable cross_t : Float.Array.t;  (** a shadow ray's crossings of clear surfaces: where, *)
  mutable cross_o : Object.t array;  (** of what *)
  mutable order : int array;  (** in the order of distance *)
  mutable ncross : int;
  fat : Color.acc;  (** the fogs' attenuation over a stretch *)
  fadd : Color.acc;  (** and their colour *)
  so : Vec3.m;  (** where a shadow ray's stretch starts *)
  sn : Vec3.m;  (** the normal where a shadow ray crosses a surface *)
  md : Medium.t;
}

let state_key =
  Scratch.key (fun () ->
      let v = Vec3.m and c () = Color.acc 0. in
      { o = v (); d = v (); p = v (); ng = v (); n = v (); wo = v (); thr = c (); acc = c (); dl = c ();
        f = c (); tr = c (); sum = c (); env_wi = v (); q = v (); uv = v (); pig = Pigment.out (); env = c (); prev_p = v (); prev_n = v ();
        num = { prev_pdf = 0. }; prev = camera_v; mat = Material.lobes (); bs = Bsdf.sampled ();
        ls = Emitter.sampled (); h = Hit.create 0.; fd = Object.found (Object.make (Shape.sphere Vec3.zero 1.));
        eh = Hit.create 0.; efd = Object.found (Object.make (Shape.sphere Vec3.zero 1.)); le = c ();
        shadow = Ray.scratch ();
        sampler = Sampler.create ~seed:0 ~pixel:0 ~sample:0; set = [||]; ph = Hit.create infinity;
        pf = Object.found (Object.make (Shape.sphere Vec3.zero 1.)); inside = []; sstart = [];
        cross_t = Float.Array.make 16 0.; cross_o = [||]; order = Array.make 16 0; ncross = 0;
        fat = c (); fadd = c (); so = v (); sn = v (); md = Medium.get () })

let dot = Vec3.dot_m

(* Light that passes straight through along a shadow ray: surfaces that
   neither refract (ior 1) nor are opaque let (f P + t) through, as a glass
   lobe with eta 1 would; anything else blocks (light bent by refraction
   is found by the paths, not by shadow rays). [blocks o]: every crossing
   of [o] blocks (one is enough to find). A crossing's filter multiplies
   [tr] of the domain's state (the shadow ray's there too). *)
let opaque_top (tex : Texture.t) =
  match tex with [] -> true | (layer : Texture.layer) :: _ -> Pigment.opaque layer.pigment

let blocks (o : Object.t) =
  o.interior.ior <> 1. || (opaque_top o.texture && (o.back == o.texture || opaque_top o.back))

let pass_through (o : Object.t) (h : Hit.t) =
  let t = h.t in
  let st = Scratch.get state_key in
  let r = st.shadow in
  Vec3.set st.q (r.ox +. (t *. r.dx)) (r.oy +. (t *. r.dy)) (r.oz +. (t *. r.dz));
  (* the interior_texture where it leaves the solid, as in whitted mode *)
  match Object.crossed_texture o st.q h r st.sn with
  | [] -> false
  | (layer : Texture.layer) :: _ ->
      if o.uv then begin
        Object.uv_into o st.q h st.uv;
        Pattern.set_uv st.uv.mx st.uv.my
      end;
      let c = st.pig in
      Pigment.into layer.pigment st.q c;
      if c.filter +. c.transmit <= 0. || o.interior.ior <> 1. then false
      else begin
        let a = st.tr in
        Color.acc_set a
          (a.ar *. ((c.filter *. c.r) +. c.transmit))
          (a.ag *. ((c.filter *. c.g) +. c.transmit))
          (a.ab *. ((c.filter *. c.b) +. c.transmit));
        not (Color.acc_is_black a)
      end

(* The light let through from [st.p] along [dir], as far as [far], into
   [st.tr] *)
let transmittance (s : Scene.t) st (dir : Vec3.m) =
  let r = st.shadow in
  Ray.set r st.p dir.mx dir.my dir.mz;
  Color.acc_set st.tr 1. 1. 1.;
  if not (Scene.occluders_s s r Ray.shadow_epsilon blocks pass_through) then Color.acc_set st.tr 0. 0. 0.

(* With volumes: [pass_through], each crossing kept (the interiors
   change there) *)
let pass_record (o : Object.t) (h : Hit.t) =
  pass_through o h
  && begin
       let st = Scratch.get state_key in
       let k = st.ncross in
       if k >= Array.length st.cross_o then begin
         let m = Int.max 16 (2 * k) in
         let ts = Float.Array.make m 0. and os = Array.make m o in
         Float.Array.blit st.cross_t 0 ts 0 k;
         Array.blit st.cross_o 0 os 0 k;
         st.cross_t <- ts;
         st.cross_o <- os;
         st.order <- Array.make m 0
       end;
       Float.Array.unsafe_set st.cross_t k h.t;
       Array.unsafe_set st.cross_o k o;
       st.ncross <- k + 1;
       true
     end

let[@inline] in_open inside = List.for_all (fun (i : Interior.t) -> i.hollow) inside

(* The stretches of a shadow ray from [st.p] along the unit vector [dir]
   to [st.shadow.far] (infinity: POV-Ray's 2e10 units), between its
   recorded crossings, each through the media of the interiors it runs
   in (starting in [st.sstart]) and, in the open, the atmosphere's
   ([air]) and the fogs' attenuation ([fog]): [st.tr] multiplied *)
let stretches t st sampler ~depth ~which ~air ~fog (dir : Vec3.m) =
  let n = st.ncross and ts = st.cross_t and ord = st.order in
  Floats.order_prefix ts n ord;
  let far = if st.shadow.far = infinity then Fog.missed else st.shadow.far in
  let lo = ref 0. and inside = ref st.sstart in
  let p = st.p and tr = st.tr and md = st.md in
  for k = 0 to n do
    let hi = if k = n then far else Float.Array.get ts ord.(k) in
    if hi > !lo && not (Color.acc_is_black tr) then begin
      let a = !lo in
      Vec3.set st.so (p.mx +. (a *. dir.mx)) (p.my +. (a *. dir.my)) (p.mz +. (a *. dir.mz));
      let op = in_open !inside in
      let ms = if op && air then t.air else [] in
      if Medium.present !inside ms then begin
        md.n.len <- hi -. a;
        Medium.transmittance md sampler (Medium.shadow_dim ~depth ~which ~cross:(k land 63)) !inside ms st.so dir tr
      end;
      if fog && op && t.fogs <> [] then begin
        Fog.blend_into t.fogs st.so dir (hi -. a) st.fat st.fadd;
        let f = st.fat in
        Color.acc_set tr (tr.ar *. f.ar) (tr.ag *. f.ag) (tr.ab *. f.ab)
      end
    end;
    if k < n then inside := Interior.beyond st.cross_o.(ord.(k)).interior !inside;
    if hi > !lo then lo := hi
  done

(* [transmittance] through the volumes too *)
let vol_transmittance t st sampler ~depth ~which ~air ~fog (dir : Vec3.m) =
  let r = st.shadow in
  Ray.set r st.p dir.mx dir.my dir.mz;
  Color.acc_set st.tr 1. 1. 1.;
  st.ncross <- 0;
  if not (Scene.occluders_s t.scene r Ray.shadow_epsilon blocks pass_record) then Color.acc_set st.tr 0. 0. 0.
  else stretches t st sampler ~depth ~which ~air ~fog dir

(* the light let through toward light [l] (its sample in [st.ls], [l]
   neither shadowless nor projected through anything: POV-Ray's fogs dim
   it only with media_attenuation and media_interaction on, its
   atmosphere with media_attenuation on), into [st.tr] *)
let[@inline] light_transmittance t st sampler ~depth ~which (l : Light.t) (dir : Vec3.m) =
  if t.volumes then
    vol_transmittance t st sampler ~depth ~which ~air:l.media_attenuation
      ~fog:(l.media_attenuation && l.media_interaction) dir
  else transmittance t.scene st dir

(* A light's projected_through object seen from [st.p] along [dir]
   (POV-Ray's rule, as in whitted mode): whether the shadow ray meets it
   (past 1e-4) before the light at [dist]; if so the ray's [far] is set
   just short of that crossing, what lies beyond casting no shadow *)
let projected st (o : Object.t) (dir : Vec3.m) dist =
  let r = st.shadow and h = st.ph in
  Ray.set r st.p dir.mx dir.my dir.mz;
  h.t <- infinity;
  h.floor <- neg_infinity;
  Object.hit_s o r 1e-4 h st.pf
  && h.t < dist
  && begin
       r.far <- h.t -. 0.001;
       true
     end

(* The random dimensions of one sample: 0-1 pixel, 2-3 lens, then a block
   per bounce. *)
let dims_per_bounce t = 8 + (2 * Array.length t.emitters)
let d_lobe = 0 and d_dir = 1 and d_rr = 3 and d_env = 4 and d_light = 6

(* the environment's light along [d] into [st.env] *)
let env_into (s : Scene.t) st (d : Vec3.m) =
  let c = st.env in
  if Sky.is_empty s.sky then (
    let b = s.background in
    Color.acc_set c b.r b.g b.b)
  else Sky.eval_into s.sky ~background:s.background d c

let rec mem (l : Light.t) (a : Light.t array) i = i < Array.length a && (Array.unsafe_get a i == l || mem l a (i + 1))

(* whether the emitter lights the vertex: a light_group's lights light
   only its surfaces, which see the global lights only with global_lights
   on; an emissive object is not a light source and lights every surface,
   as the paths that hit it do *)
let lights_vertex (s : Scene.t) (st : state) = function
  | Emitter.Delta l | Emitter.Area { light = l; _ } -> Array.length s.light_sets = 1 || mem l st.set 0
  | Emitter.Sphere _ -> true

(* The light an emissive sphere [obj] sends to [st.p] along [wi] (a
   direction sampled toward it), into [st.le]: seen when the first
   surface met is the sphere's, or through clear surfaces (ior 1: the
   paths that pass through them keep their light sampling's weight) to
   it; through the volumes, whatever lights' flags say (paths cross
   them). [false]: not seen. *)
let sphere_seen t st sampler ~depth ~which (obj : Object.t) (wi : Vec3.m) =
  let s = t.scene in
  let eh = st.eh and efd = st.efd in
  let p = st.p and q = st.q and le = st.le in
  if Scene.intersect_into s p wi Ray.epsilon infinity eh efd then
    if efd.leaf == obj then begin
      let th = eh.t in
      Vec3.set q (p.mx +. (th *. wi.mx)) (p.my +. (th *. wi.my)) (p.mz +. (th *. wi.mz));
      Emitter.emission_into obj q st.pig le;
      if t.volumes then begin
        (* nothing crossed on the way *)
        Color.acc_set st.tr 1. 1. 1.;
        st.ncross <- 0;
        st.shadow.far <- th;
        stretches t st sampler ~depth ~which ~air:true ~fog:true wi;
        let tr = st.tr in
        Color.acc_set le (le.ar *. tr.ar) (le.ag *. tr.ag) (le.ab *. tr.ab)
      end;
      true
    end
    else if blocks efd.leaf then false
    else begin
      let r = st.shadow in
      Ray.set r p wi.mx wi.my wi.mz;
      eh.t <- infinity;
      eh.floor <- neg_infinity;
      Object.hit_s obj r Ray.epsilon eh efd
      && begin
           let th = eh.t in
           Vec3.set q (p.mx +. (th *. wi.mx)) (p.my +. (th *. wi.my)) (p.mz +. (th *. wi.mz));
           Emitter.emission_into obj q st.pig le;
           (* short of the sphere itself *)
           st.shadow.far <- th *. (1. -. 1e-9);
           if t.volumes then vol_transmittance t st sampler ~depth ~which ~air:true ~fog:true wi
           else transmittance s st wi;
           let tr = st.tr in
           Color.acc_set le (le.ar *. tr.ar) (le.ag *. tr.ag) (le.ab *. tr.ab);
           not (Color.acc_is_black le)
         end
    end
  else false

(* The light of delta or area light [l] sampled in [st.ls] let through
   to [st.p], into [st.tr] *)
let light_seen t st sampler ~depth ~which (l : Light.t) =
  let tr = st.tr and ls = st.ls in
  (* projected_through: a condition on the light's visibility *)
  match l.projected_through with
  | None ->
      if l.shadowless then Color.acc_set tr 1. 1. 1.
      else begin
        (* POV-Ray's shadow tolerance, as in whitted mode (Shadow.shadow_into) *)
        st.shadow.far <- ls.n.dist -. Ray.shadow_epsilon;
        light_transmittance t st sampler ~depth ~which l ls.wi
      end
  | Some o ->
      if not (projected st o ls.wi ls.n.dist) then Color.acc_set tr 0. 0. 0.
      else if l.shadowless then Color.acc_set tr 1. 1. 1.
      else light_transmittance t st sampler ~depth ~which l ls.wi

(* the environment's light along [wi] let through to [st.p] (through
   the volumes), into [st.env]; false where it is blocked *)
let env_seen t st sampler ~depth ~which (wi : Vec3.m) =
  st.shadow.far <- infinity;
  if t.volumes then vol_transmittance t st sampler ~depth ~which ~air:true ~fog:true wi
  else transmittance t.scene st wi;
  let tr = st.tr in
  (not (Color.acc_is_black tr))
  && begin
       env_into t.scene st wi;
       let c = st.env in
       Color.acc_set c (tr.ar *. c.ar) (tr.ag *. c.ag) (tr.ab *. c.ab);
       true
     end

(* Next-event estimation at the vertex: every emitter that lights it, plus
   the environment, into [st.dl]. A shadow ray starts in the interiors
   the path arrived in (the side of the surface it lights). *)
let direct t (st : state) sampler ~depth base =
  let dl = st.dl and m = st.mat and n = st.n and wo = st.wo and f = st.f in
  Color.acc_set dl 0. 0. 0.;
  st.sstart <- st.inside;
  let ne = Array.length t.emitters in
  for i = 0 to ne - 1 do
    let e = Array.unsafe_get t.emitters i in
    let ls = st.ls in
    if
      lights_vertex t.scene st e
      && Emitter.sample_into e st.p
        (Sampler.get sampler (base + d_light + (2 * i)))
        (Sampler.get sampler (base + d_light + (2 * i) + 1))
        ls
    then begin
      let ci = dot n ls.wi in
      if ci > 0. then begin
        Bsdf.eval_into m n wo ls.wi f;
        if not (Color.acc_is_black f) then
          match e with
          | Delta l | Area { light = l; _ } ->
              light_seen t st sampler ~depth ~which:i l;
              let tr = st.tr and v = ls.value in
              Color.acc_set dl
                (dl.ar +. (ci *. (f.ar *. (tr.ar *. v.ar))))
                (dl.ag +. (ci *. (f.ag *. (tr.ag *. v.ag))))
                (dl.ab +. (ci *. (f.ab *. (tr.ab *. v.ab))))
          | Sphere { obj; _ } ->
              if sphere_seen t st sampler ~depth ~which:i obj ls.wi then begin
                let le = st.le in
                let pb = Bsdf.pdf_m m n wo ls.wi in
                let k = ci *. power ls.n.pdf pb /. ls.n.pdf in
                Color.acc_set dl
                  (dl.ar +. (k *. (f.ar *. le.ar)))
                  (dl.ag +. (k *. (f.ag *. le.ag)))
                  (dl.ab +. (k *. (f.ab *. le.ab)))
              end
      end
    end
  done;
  (* the environment is sampled cosine-weighted about the normal *)
  if t.has_env then begin
    let wi = st.env_wi in
    Bsdf.around_into wi n.mx n.my n.mz
      (Float.sqrt (1. -. Sampler.get sampler (base + d_env)))
      (2. *. Float.pi *. Sampler.get sampler (base + d_env + 1));
    let ci = dot n wi in
    if ci > 0. then begin
      Bsdf.eval_into m n wo wi f;
      if (not (Color.acc_is_black f)) && env_seen t st sampler ~depth ~which:ne wi then begin
        let pl = ci /. Float.pi and pb = Bsdf.pdf_m m n wo wi in
        let c = st.env in
        let k = ci *. power pl pb /. pl in
        Color.acc_set dl
          (dl.ar +. (k *. (f.ar *. c.ar)))
          (dl.ag +. (k *. (f.ag *. c.ag)))
          (dl.ab +. (k *. (f.ab *. c.ab)))
      end
    end
  end

(* Next-event estimation at a point in a medium, scattering by [md.phase]
   the light of every emitter that lights media (POV-Ray's: the global
   lights with media_interaction on and not shadowless; emissive spheres)
   and the environment (sampled uniformly over the sphere), into
   [st.dl]. *)
let direct_medium t (st : state) sampler ~depth base =
  let s = t.scene in
  let dl = st.dl and md = st.md and d = st.d in
  let sc = md.phase in
  Color.acc_set dl 0. 0. 0.;
  st.sstart <- st.inside;
  st.set <- s.lights;
  let ne = Array.length t.emitters in
  for i = 0 to ne - 1 do
    let e = Array.unsafe_get t.emitters i in
    let ls = st.ls in
    let lights_media =
      match e with
      | Delta l | Area { light = l; _ } -> l.media_interaction && (not l.shadowless) && lights_vertex s st e
      | Sphere _ -> true
    in
    if
      lights_media
      && Emitter.sample_into e st.p
        (Sampler.get sampler (base + d_light + (2 * i)))
        (Sampler.get sampler (base + d_light + (2 * i) + 1))
        ls
    then begin
      Medium.phase_at md sc (dot ls.wi d);
      let ph = md.n.ph in
      if ph > 0. then
        match e with
        | Delta l | Area { light = l; _ } ->
            (* a spotlight's samples outside its cone bring nothing *)
            if not (Color.acc_is_black ls.value) then begin
              light_seen t st sampler ~depth ~which:i l;
              let tr = st.tr and v = ls.value in
              Color.acc_set dl
                (dl.ar +. (ph *. (tr.ar *. v.ar)))
                (dl.ag +. (ph *. (tr.ag *. v.ag)))
                (dl.ab +. (ph *. (tr.ab *. v.ab)))
            end
        | Sphere { obj; _ } ->
            let pb = md.n.pdf in
            if sphere_seen t st sampler ~depth ~which:i obj ls.wi then begin
              let le = st.le in
              let k = ph *. power ls.n.pdf pb /. ls.n.pdf in
              Color.acc_set dl (dl.ar +. (k *. le.ar)) (dl.ag +. (k *. le.ag)) (dl.ab +. (k *. le.ab))
            end
    end
  done;
  if t.has_env then begin
    let wi = st.env_wi in
    Bsdf.around_into wi d.mx d.my d.mz
      (1. -. (2. *. Sampler.get sampler (base + d_env)))
      (2. *. Float.pi *. Sampler.get sampler (base + d_env + 1));
    Medium.phase_at md sc (dot wi d);
    let ph = md.n.ph and pb = md.n.pdf in
    if ph > 0. && env_seen t st sampler ~depth ~which:ne wi then begin
      let pl = Medium.inv4pi in
      let c = st.env and k = ph *. power pl pb /. pl in
      Color.acc_set dl (dl.ar +. (k *. c.ar)) (dl.ag +. (k *. c.ag)) (dl.ab +. (k *. c.ab))
    end
  end

(* The spare dimensions of a bounce's block: a stretch's free flight in
   homogeneous media *)
let d_free t = 6 + (2 * Array.length t.emitters)

(* A path's stretch of [st.md.n.len] units from [st.o] along [st.d]
   (a surface there, or the sky at POV-Ray's 2e10 units) through the
   volumes: its media's emission and the fogs' colour added to [st.acc],
   the throughput dimmed; true where the media scatter the path (at
   [st.md.n.t]). The fogs lay over the media as in whitted mode: the
   media's emission is seen through the fogs over the whole stretch. *)
let volume_stretch t (st : state) sampler ~depth base =
  let md = st.md and thr = st.thr and acc = st.acc and o = st.o and d = st.d in
  let inside = st.inside in
  let op = in_open inside in
  let air = if op then t.air else [] in
  let fogged = op && t.fogs <> [] in
  md.scattered <- false;
  let mediated = Medium.present inside air in
  if mediated then begin
    Medium.segment md sampler ~depth ~dim:(base + d_free t) inside air o d thr;
    let em = md.em in
    if fogged then begin
      Fog.blend_into t.fogs o d md.n.len st.fat st.fadd;
      let f = st.fat in
      Color.acc_set em (em.ar *. f.ar) (em.ag *. f.ag) (em.ab *. f.ab)
    end;
    Color.acc_set acc (acc.ar +. (thr.ar *. em.ar)) (acc.ag +. (thr.ag *. em.ag)) (acc.ab +. (thr.ab *. em.ab))
  end;
  if fogged then begin
    Fog.blend_into t.fogs o d (if md.scattered then md.n.t else md.n.len) st.fat st.fadd;
    let f = st.fat and c = st.fadd in
    Color.acc_set acc (acc.ar +. (thr.ar *. c.ar)) (acc.ag +. (thr.ag *. c.ag)) (acc.ab +. (thr.ab *. c.ab));
    Color.acc_set thr (thr.ar *. f.ar) (thr.ag *. f.ag) (thr.ab *. f.ab)
  end;
  if mediated then begin
    let w = md.w in
    Color.acc_set thr (thr.ar *. w.ar) (thr.ag *. w.ag) (thr.ab *. w.ab)
  end;
  (* the rainbows, laid over what comes from the stretch's end before
     the atmosphere and the fogs, as in whitted mode *)
  if op && t.rainbows <> [] then begin
    Rainbow.layer t.rainbows d (if md.scattered then md.n.t else md.n.len) st.fat st.fadd;
    let a = st.fat and b = st.fadd in
    Color.acc_set acc (acc.ar +. (thr.ar *. b.ar)) (acc.ag +. (thr.ag *. b.ag)) (acc.ab +. (thr.ab *. b.ab));
    Color.acc_set thr (thr.ar *. a.ar) (thr.ag *. a.ag) (thr.ab *. a.ab)
  end;
  md.scattered

(* Russian roulette after three bounces; false: the path ends *)
let[@inline] survives (st : state) sampler ~depth base =
  let thr = st.thr in
  let q = if depth >= 3 then fmin 0.95 (fmax thr.ar (fmax thr.ag thr.ab)) else 1. in
  if q <= 0. || Sampler.get sampler (base + d_rr) >= q then false
  else begin
    let k = 1. /. q in
    Color.acc_set thr (k *. thr.ar) (k *. thr.ag) (k *. thr.ab);
    true
  end

(* The path scattered in a medium at [st.md.n.t] along the ray: light
   sampled from there, a new direction by the medium's phase function;
   false: the path ends *)
let medium_vertex t (st : state) sampler ~max_depth ~depth base =
  let md = st.md and o = st.o and d = st.d and p = st.p in
  let x = md.n.t in
  Vec3.set p (o.mx +. (x *. d.mx)) (o.my +. (x *. d.my)) (o.mz +. (x *. d.mz));
  depth < max_depth
  && begin
       let thr = st.thr and acc = st.acc in
       if t.nee then begin
         direct_medium t st sampler ~depth base;
         let dl = st.dl in
         Color.acc_set acc (acc.ar +. (thr.ar *. dl.ar)) (acc.ag +. (thr.ag *. dl.ag)) (acc.ab +. (thr.ab *. dl.ab))
       end;
       let wi = st.bs.wi in
       Medium.sample_phase md md.phase d
         (Sampler.get sampler (base + d_dir))
         (Sampler.get sampler (base + d_dir + 1))
         wi;
       let k = md.n.ph /. md.n.pdf in
       Color.acc_set thr (k *. thr.ar) (k *. thr.ag) (k *. thr.ab);
       survives st sampler ~depth base
       && begin
            st.prev <- medium_v;
            Vec3.set st.prev_p p.mx p.my p.mz;
            st.num.prev_pdf <- md.n.pdf;
            Vec3.set o p.mx p.my p.mz;
            Vec3.set d wi.mx wi.my wi.mz;
            true
          end
     end

(* One radiance sample along the ray in [st.o], [st.d], into [st.acc]. *)
let li_into t sampler ~max_depth (st : state) =
  let s = t.scene in
  let per = dims_per_bounce t in
  let thr = st.thr and acc = st.acc and o = st.o and d = st.d in
  Color.acc_set thr 1. 1. 1.;
  Color.acc_set acc 0. 0. 0.;
  st.prev <- camera_v;
  if t.volumes then st.inside <- Whitted.start_media s o;
  let depth = ref 0 and go = ref true in
  while !go do
    let tmin = if !depth = 0 then 0. else Ray.epsilon in
    (* POV-Ray's no_image and no_reflection: the camera ray sees the image
       view, every later ray the reflected one *)
    let s = if !depth = 0 then Scene.image s else Scene.reflected s in
    let h = st.h and fd = st.fd in
    let hit = Scene.intersect_into s o d tmin infinity h fd in
    let base = 4 + (!depth * per) in
    let scattered =
      t.volumes
      && begin
           st.md.n.len <- (if hit then h.t else Fog.missed);
           volume_stretch t st sampler ~depth:!depth base
         end
    in
    if scattered then begin
      if medium_vertex t st sampler ~max_depth ~depth:!depth base then incr depth else go := false
    end
    else if not hit then begin
      go := false;
      if t.has_env then begin
        let w =
          if st.prev = smooth_v && t.nee then
            power st.num.prev_pdf (fmax 0. (dot st.prev_n d) /. Float.pi)
          else if st.prev = medium_v && t.nee then power st.num.prev_pdf Medium.inv4pi
          else 1.
        in
        env_into s st d;
        let c = st.env in
        Color.acc_set acc
          (acc.ar +. (w *. (thr.ar *. c.ar)))
          (acc.ag +. (w *. (thr.ag *. c.ag)))
          (acc.ab +. (w *. (thr.ab *. c.ab)))
      end
    end
    else begin
      let obj = fd.leaf and th = h.t in
      st.set <- Array.unsafe_get s.light_sets obj.lights;
      let p = st.p and ng = st.ng and n = st.n and wo = st.wo in
      Vec3.set p (o.mx +. (th *. d.mx)) (o.my +. (th *. d.my)) (o.mz +. (th *. d.mz));
      Scene.hit_normal_into s fd h p ng;
      Vec3.set wo (-.d.mx) (-.d.my) (-.d.mz);
      let entering = dot ng d < 0. in
      if entering then Vec3.set n ng.mx ng.my ng.mz else Vec3.set n (-.ng.mx) (-.ng.my) (-.ng.mz);
      (* a ray leaving a solid travelled inside it: interior fade (white,
         which changes nothing, without a fade distance) *)
      if (not entering) && obj.interior.fade_distance <> 0. then begin
        let i = obj.interior in
        let c = i.fade_color in
        Color.acc_set thr
          (thr.ar *. Interior.fade_channel i c.r th)
          (thr.ag *. Interior.fade_channel i c.g th)
          (thr.ab *. Interior.fade_channel i c.b th)
      end;
      let m = st.mat in
      Pattern.set_normal ng;
      if obj.uv then begin
        Object.uv_into obj p h st.uv;
        Pattern.set_uv st.uv.mx st.uv.my
      end;
      (* a texture's normal makes [m]'s shading normal: the lobes are
         seen about it here and in [direct], [n] deciding the sides *)
      Material.into m (if entering then obj.texture else obj.back) obj.interior p n wo ~entering;
      if not (Color.acc_is_black m.em) then begin
        let w =
          if (st.prev = smooth_v || st.prev = medium_v) && t.nee then
            match Emitter.find_index t.emitters obj with
            | -1 -> 1.
            | i ->
                power st.num.prev_pdf
                  (Emitter.pdf_m t.emitters.(i) st.prev_p p ng)
          else 1.
        in
        let em = m.em in
        Color.acc_set acc
          (acc.ar +. (w *. (thr.ar *. em.ar)))
          (acc.ag +. (w *. (thr.ag *. em.ag)))
          (acc.ab +. (w *. (thr.ab *. em.ab)))
      end;
      if !depth >= max_depth then go := false
      else begin
        if t.nee && Bsdf.has_smooth_m m then begin
          direct t st sampler ~depth:!depth base;
          let dl = st.dl in
          Color.acc_set acc (acc.ar +. (thr.ar *. dl.ar)) (acc.ag +. (thr.ag *. dl.ag)) (acc.ab +. (thr.ab *. dl.ab))
        end;
        let bs = st.bs in
        if
          not
            (Bsdf.sample_into m n wo
               (Sampler.get sampler (base + d_lobe))
               (Sampler.get sampler (base + d_dir))
               (Sampler.get sampler (base + d_dir + 1))
               bs)
        then go := false
        else begin
          let bw = bs.weight in
          Color.acc_set thr (thr.ar *. bw.ar) (thr.ag *. bw.ag) (thr.ab *. bw.ab);
          if not (survives st sampler ~depth:!depth base) then go := false
          else begin
            (* straight through a clear surface (ior 1): the light found
               beyond is weighed as if the surface were not there, by the
               last vertex that sampled light *)
            if bs.delta then begin
              if obj.interior.ior <> 1. || dot bs.wi d < 1. -. 1e-9 then st.prev <- specular_v
            end
            else begin
              st.prev <- smooth_v;
              Vec3.set st.prev_p p.mx p.my p.mz;
              Vec3.set st.prev_n n.mx n.my n.mz;
              st.num.prev_pdf <- bs.p.pdf
            end;
            (* through the surface: into or out of its interior *)
            if t.volumes && dot n bs.wi < 0. then st.inside <- Interior.beyond obj.interior st.inside;
            Vec3.set o p.mx p.my p.mz;
            Vec3.set d bs.wi.mx bs.wi.my bs.wi.mz;
            incr depth
          end
        end
      end
    end
  done

let li t sampler ~max_depth (ray : Ray.t) =
  let st = Scratch.get state_key in
  Vec3.load st.o ray.origin;
  Vec3.load st.d ray.dir;
  li_into t sampler ~max_depth st;
  Color.of_acc st.acc

let pixel_into t ~width ~height ~seed ~spp ~max_depth x y (out : Color.acc) =
  let st = Scratch.get state_key in
  let cam = t.scene.camera and sampler = st.sampler and sum = st.sum in
  let side = int_of_float (Float.sqrt (float_of_int spp)) in
  let strat = side * side = spp in
  Color.acc_set sum 0. 0. 0.;
  for k = 0 to spp - 1 do
    Sampler.reset sampler ~seed ~pixel:((y * width) + x) ~sample:k;
    let u1 = Sampler.get sampler 0 and u2 = Sampler.get sampler 1 in
    let jx = if strat then (float_of_int (k mod side) +. u1) /. float_of_int side else u1
    and jy = if strat then (float_of_int (k / side) +. u2) /. float_of_int side else u2 in
    let sx = Camera.pixel_x ~width (float_of_int x +. jx)
    and sy = Camera.pixel_y ~height (float_of_int y +. jy) in
    let seen =
      if cam.aperture = 0. then Camera.ray_into cam sx sy st.o st.d
      else Camera.lens_into cam sx sy (Sampler.get sampler 2) (Sampler.get sampler 3) st.o st.d
    in
    (* a point the camera sends no ray through stays black, as in POV-Ray *)
    if seen then li_into t sampler ~max_depth st else Color.acc_set st.acc 0. 0. 0.;
    let c = st.acc in
    (* a non-finite sample (never expected) would poison the pixel: drop it *)
    if Float.is_finite (c.ar +. c.ag +. c.ab) then
      Color.acc_set sum (sum.ar +. c.ar) (sum.ag +. c.ag) (sum.ab +. c.ab)
  done;
  let k = 1. /. float_of_int spp in
  Color.acc_set out (k *. sum.ar) (k *. sum.ag) (k *. sum.ab)

let pixel t ~width ~height ~seed ~spp ~max_depth x y =
  let out = Color.acc 0. in
  pixel_into t ~width ~height ~seed ~spp ~max_depth x y out;
  Color.of_acc out
