(* POV-Ray 3.7's classic recursive ray tracer (see whitted.mli): the
   surface seen along a ray, its texture's layers lit ({!Direct}, with
   {!Shadow}), and the rays it reflects and lets through. *)

open Color

(* [Vec3.dot], in place: the same arithmetic *)
let dot = Vec3.dot_m

(* A nesting level's scalars, stored flat, so that passing them
   allocates nothing: the level's ADC weight, the
   weight of a reflection being traced ([refl]) and of the ray traced
   next from here ([child], read by [trace_ray] as it starts). *)
type nums = {
  mutable weight : float;
  mutable refl : float;
  mutable child : float;
  mutable dist : float;  (** how far the ray traced from here last met a surface (infinity: none) *)
  mutable fres : float;  (** the index ratio a fresnel reflection is weighed by ({!Interior.fresnel_ior}) *)
}

let nums () = { weight = 1.; refl = 1.; child = 1.; dist = infinity; fres = 1. }

(* Heckbert's k < 0: no refracted ray at this relative index and cosine *)
let[@inline] total_internal eta cos_i = eta > 1. && 1. +. (eta *. eta *. ((cos_i *. cos_i) -. 1.)) < 0.

(* [d] mirrored about [n] into [rd], mended as POV-Ray mends it where a
   perturbed [n] sends it below the surface (whose normal [n0] faces the
   ray): about [n0] instead when [n] itself faces away from the eye,
   else mirrored back above the surface about [n0] *)
let mirror (d : Vec3.m) (n : Vec3.m) (n0 : Vec3.m) (rd : Vec3.m) =
  let m = -2. *. dot d n in
  Vec3.set rd (d.mx +. (m *. n.mx)) (d.my +. (m *. n.my)) (d.mz +. (m *. n.mz));
  let below = dot rd n0 in
  if below < 0. then
    if dot rd n < 0. then begin
      let m = -2. *. dot d n0 in
      Vec3.set rd (d.mx +. (m *. n0.mx)) (d.my +. (m *. n0.my)) (d.mz +. (m *. n0.mz))
    end
    else
      let m = -2. *. below in
      Vec3.set rd (rd.mx +. (m *. n0.mx)) (rd.my +. (m *. n0.my)) (rd.mz +. (m *. n0.mz))

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
  a : Direct.opacity;  (** the opacity of the layer being shaded *)
  pig : Pigment.out;  (** its pigment *)
  fade : Color.acc;  (** the fade of the medium the ray came through *)
  uv : Vec3.m;  (** the hit's <u, v, 0>, when [has_uv] (the object's texture is uv-mapped) *)
  mutable has_uv : bool;
  sh : Direct.shadows;  (** the shadows found at [p] *)
  mutable lights : Light.t array;  (** the lights of the surface at [p] (its light set) *)
  mutable chain : Transform.t array;
      (** the frames of the texture maps whose entry is being shaded,
          outermost first, [nchain] of them: a layer's normal is
          perturbed in the innermost one's space, as POV-Ray 3.7 does
          (trace.cpp's ComputeLightedTexture: Warp_Normal through each
          patterned texture above the layer, then back) *)
  mutable nchain : int;
  tn : Vec3.m;  (** the normal turned into that space *)
  amb : Color.acc;  (** the radiosity gathered at [p], once [amb_done] *)
  mutable amb_done : bool;
  kr : Color.acc;  (** the reflectivity of the layer being shaded *)
  dl : Color.acc;  (** the direct light of the layer being shaded *)
  h : Hit.t;  (** the hit of the ray this frame traces *)
  hf : Object.found;  (** its object *)
  sky : Vec3.m;  (** the unit direction of a ray that meets nothing *)
  q : Scene.query;  (** the records of the frame's query of the scene *)
  mutable collect : bool;  (** the surface gathers photons (the scene has some, it does not say collect off) *)
}

let new_frame () =
  let h, hf = Scene.new_records () in
  { c = Color.acc 0.; tr = Color.acc 1.; rf = Color.acc 0.; p = Vec3.m (); n0 = Vec3.m ();
    top = Vec3.m (); top_set = false; pn = Vec3.m (); rd = Vec3.m (); rc = Color.acc 0.;
    k = nums (); a = { alpha = 1. }; pig = Pigment.out (); fade = Color.acc 1.;
    uv = Vec3.m (); has_uv = false; sh = Direct.shadows (); lights = [||]; chain = [||]; nchain = 0;
    tn = Vec3.m (); amb = Color.acc 0.; amb_done = false; kr = Color.acc 0.; collect = false;
    dl = Color.acc 0.; h; hf; sky = Vec3.m (); q = Scene.query () }

(* a texture map's frame entered (the chain grows once, to the deepest
   nesting met) *)
let chain_push fr t =
  let n = fr.nchain in
  if n = Array.length fr.chain then fr.chain <- Array.append fr.chain (Array.make (Int.max 4 n) t);
  Array.unsafe_set fr.chain n t;
  fr.nchain <- n + 1

let frames_key = Scratch.key (fun () -> Scratch.levels ~initial:8 new_frame)

(* the next frame of the domain's [frames] (from [frames_key]) *)
let enter frames =
  let f = Scratch.push frames in
  Color.acc_set f.c 0. 0. 0.;
  Color.acc_set f.tr 1. 1. 1.;
  f.top_set <- false;
  f.amb_done <- false;
  Color.acc_set f.amb 0. 0. 0.;
  Direct.forget f.sh;
  f

let leave frames = Scratch.pop frames

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

let[@inline] set_color (out : Color.acc) (c : Color.t) = Color.acc_set out c.r c.g c.b

(* the numbers turning a gather's directions (per domain) *)
let gather_key = Scratch.key (fun () -> Sampler.create ~seed:0 ~pixel:0 ~sample:0)

(* a ray's direction made unit, to look up the rainbows (per domain) *)
let sky_key = Scratch.key Vec3.m

(* a surface's own light [c] and, through it ([tr], faded), the light [rc]
   from beyond *)
let[@inline] through (out : Color.acc) (c : Color.acc) (tr : Color.acc) (fade : Color.acc) (rc : Color.acc) =
  Color.acc_set out
    (c.ar +. ((tr.ar *. fade.ar) *. rc.ar))
    (c.ag +. ((tr.ag *. fade.ag) *. rc.ag))
    (c.ab +. ((tr.ab *. fade.ab) *. rc.ab))

(* What a ray in the open (inside no solid but hollow ones: POV-Ray's
   hollow ray) brings back through the scene's fogs: from the sky, or
   from the point [p] it hit (its distance found here, not carried: a
   float live across the shading would be boxed for every ray). *)
let[@inline] in_open media = List.for_all (fun (i : Interior.t) -> i.hollow) media

let[@inline] fogged_sky (s : Scene.t) o d media out =
  match s.fog with [] -> () | fogs -> if in_open media then Fog.apply fogs o d infinity out

let[@inline] fogged_hit (s : Scene.t) (o : Vec3.m) (d : Vec3.m) (p : Vec3.m) media out =
  match s.fog with
  | [] -> ()
  | fogs ->
      if in_open media then begin
        let dx = p.mx -. o.mx and dy = p.my -. o.my and dz = p.mz -. o.mz in
        let t = Float.sqrt (((dx *. dx) +. (dy *. dy) +. (dz *. dz)) /. ((d.mx *. d.mx) +. (d.my *. d.my) +. (d.mz *. d.mz))) in
        Fog.apply fogs o d t out
      end

(* What a ray inside solids with media brings back from the point [p] it
   hit, through them (see {!Volume}). As POV-Ray 3.7, only a hollow ray
   (inside hollow solids alone) meets media: inside a solid that is not
   hollow, its own media and those of the solids around it are not
   computed (measured: an emitting sphere not hollow shows nothing, one
   inside a hollow emitting sphere shows the outer's media in the shell
   only). *)
let rec has_media = function [] -> false | (i : Interior.t) :: r -> i.media <> [] || has_media r

let[@inline never] mediated_hit (s : Scene.t) (o : Vec3.m) (d : Vec3.m) (p : Vec3.m) media out =
  if has_media media && in_open media then begin
    let dx = p.mx -. o.mx and dy = p.my -. o.my and dz = p.mz -. o.mz in
    let t = Float.sqrt (((dx *. dx) +. (dy *. dy) +. (dz *. dz)) /. ((d.mx *. d.mx) +. (d.my *. d.my) +. (d.mz *. d.mz))) in
    Volume.apply s o d t ~starts:media media out
  end

(* POV-Ray lays its rainbows over what a ray in the open brings back
   from [dist] units away, before the atmosphere and the fog *)
let rainbowed (s : Scene.t) (d : Vec3.m) dist out =
  let u = Scratch.get sky_key in
  Vec3.set u d.mx d.my d.mz;
  Vec3.normalize_m u;
  Rainbow.apply s.rainbows u dist out

(* Scene-level (atmospheric) media: seen by a ray in the open (as fog),
   after the media of the hollow solids it is inside, as a second layer
   (POV-Ray 3.7 does so, measured: the atmosphere's emission inside a
   hollow sphere is not dimmed by the sphere's absorbing media, the
   sphere's emission is dimmed by the atmosphere's absorption); a ray
   that hits nothing crosses POV-Ray's 2e10 units of it (measured:
   absorption 1e-10 before a white background gives exp(-2)). Inside a
   solid, its own media alone. *)
let[@inline never] aired_hit (s : Scene.t) (o : Vec3.m) (d : Vec3.m) (p : Vec3.m) media out =
  let dx = p.mx -. o.mx and dy = p.my -. o.my and dz = p.mz -. o.mz in
  let t = Float.sqrt (((dx *. dx) +. (dy *. dy) +. (dz *. dz)) /. ((d.mx *. d.mx) +. (d.my *. d.my) +. (d.mz *. d.mz))) in
  if in_open media then begin
    if media <> [] && s.settings.object_media then Volume.apply s o d t ~starts:media media out;
    if s.rainbows <> [] then rainbowed s d (Float.sqrt ((dx *. dx) +. (dy *. dy) +. (dz *. dz))) out;
    if s.atmosphere <> [] then Volume.apply s o d t ~starts:media s.atmosphere out
  end

let[@inline never] aired_sky (s : Scene.t) (o : Vec3.m) (d : Vec3.m) media out =
  if in_open media then begin
    let dl = Float.sqrt ((d.mx *. d.mx) +. (d.my *. d.my) +. (d.mz *. d.mz)) in
    Volume.apply s o d (Fog.missed /. dl) ~starts:media s.atmosphere out
  end

(* POV-Ray's iridescence, on the reflected light [rc]: a thin film of
   {!Direct.irid_thickness} seen at cosines [ci] in and [cr] out shifts
   each channel's phase by its wavelength (amount and wavelengths in
   single precision) *)
let irid (s : Scene.t) (f : Finish.t) (p : Vec3.m) ci cr (rc : Color.acc) =
  let t = Direct.irid_thickness f p in
  let phase = 2. *. Float.pi *. t *. (Float.abs ci +. cr) in
  let wl = s.settings.irid_wavelength and a = Direct.single f.irid in
  Color.acc_set rc
    (rc.ar *. (1. +. (a *. Float.cos (phase /. Direct.single wl.r))))
    (rc.ag *. (1. +. (a *. Float.cos (phase /. Direct.single wl.g))))
    (rc.ab *. (1. +. (a *. Float.cos (phase /. Direct.single wl.b))))

(* The ray from [o] along [d], hits between [tmin] and [tmax] (infinity
   but for a mesh camera's maximum distance), its radiance into [out];
   its ADC weight is [from.child]; [media]: the interiors the ray is
   inside, innermost first. [o] and [d] belong to the caller and are
   not written. *)
let rec trace_ray (s : Scene.t) tmin tmax (o : Vec3.m) (d : Vec3.m) level (from : nums) media (out : Color.acc) =
  let weight = from.child in
  from.dist <- infinity;
  if level > s.settings.max_trace_level || weight < s.settings.adc_bailout then Color.acc_set out 0. 0. 0.
  else
    (* the frame for a ray that meets nothing too: its records and
       scratch are reached from it, not looked up one by one *)
    let frames = Scratch.get frames_key in
    let fr = enter frames in
    let h = fr.h and f = fr.hf in
    if not (Scene.intersect_with s fr.q o d tmin tmax h f) then begin
      if Sky.is_empty s.sky then set_color out s.background
      else begin
        let u = fr.sky in
        Vec3.set u d.mx d.my d.mz;
        Vec3.normalize_m u;
        Sky.eval_into s.sky ~background:s.background u out
      end;
      if s.rainbows <> [] && in_open media then rainbowed s d Fog.missed out;
      if s.atmosphere <> [] then aired_sky s o d media out;
      fogged_sky s o d media out;
      leave frames
    end
    else begin
      let t = h.t and obj = f.leaf in
      from.dist <- t;
      (* POV-Ray draws no highlights where gather rays meet a surface *)
      (match s.settings.radiosity with
      | None -> Direct.set_highlights fr.sh true
      | Some _ -> Direct.set_highlights fr.sh (Radiosity.depth () = 0));
      let p = fr.p in
      Vec3.set p (o.mx +. (t *. d.mx)) (o.my +. (t *. d.my)) (o.mz +. (t *. d.mz));
      Scene.hit_normal_into s f h p fr.n0;
      fr.has_uv <- obj.uv;
      if obj.uv then Object.uv_into obj p h fr.uv;
      (* POV-Ray fades what comes through the far side of a medium, not
         the far surface's own shading, and only where the ray leaves
         the object it hits (its interior is one the ray is in), by that
         interior's fade over the whole way here (trace.cpp's
         ComputeLightedTexture): a ray that leaves a solid through a
         clipped-away hole is not faded by it *)
      let fade = fr.fade in
      let i = obj.interior in
      if i.fade_distance <> 0. && List.memq i media then begin
        let c = i.fade_color in
        Color.acc_set fade (Interior.fade_channel i c.r t) (Interior.fade_channel i c.g t) (Interior.fade_channel i c.b t)
      end
      else Color.acc_set fade 1. 1. 1.;
      fr.k.weight <- weight;
      shade s d obj fr level media fade out;
      if s.atmosphere <> [] || s.rainbows <> [] then aired_hit s o d p media out
      else if s.settings.object_media && has_media media then mediated_hit s o d p media out;
      fogged_hit s o d p media out;
      leave frames
    end

(* [fr.n0] holds the surface's normal, turned to face the ray here;
   [fr.k.weight] the ray's weight *)
and shade s (d : Vec3.m) (obj : Object.t) fr level media (fade : Color.acc) (out : Color.acc) =
  let weight = fr.k.weight in
  let n0 = fr.n0 in
  (* the slope pattern reads the surface's own (outward) normal *)
  Pattern.set_normal n0;
  let entering = dot n0 d < 0. in
  if not entering then Vec3.set n0 (-.n0.mx) (-.n0.my) (-.n0.mz);
  (* a light_group's surfaces see only their own set of lights *)
  (let ls = Array.unsafe_get s.light_sets obj.lights in
   if fr.lights != ls then fr.lights <- ls);
  fr.collect <-
    (match s.settings.photons with
    | None -> false
    | Some { state = { map = Some m }; _ } -> obj.photon.collect && Photon.size m > 0
    | Some _ -> false);
  let inner = obj.interior in
  let eta = Interior.relative_ior inner media in
  fr.k.fres <- Interior.fresnel_ior inner media;
  let bailout = s.settings.adc_bailout in
  (* guessed from the unperturbed normal; shaded again in the rare case
     the top layer's normal or an opaque texture says otherwise *)
  let guess = total_internal eta (-.dot d n0) in
  let c = fr.c and tr = fr.tr in
  let tex = if entering then obj.texture else obj.back in
  layers s d level media fr (not guess) c tr fr.p tex;
  let n = if fr.top_set then fr.top else n0 in
  (* what the texture lets through, by its size: POV-Ray takes absolute
     values (a negative transmit, as in transmitfx.pov, lets the picture
     behind through with its sign turned) *)
  if guess <> (Float.abs (Color.acc_luminance tr) > bailout && total_internal eta (-.dot d n)) then begin
    fr.top_set <- false;
    Color.acc_set c 0. 0. 0.;
    Color.acc_set tr 1. 1. 1.;
    layers s d level media fr guess c tr fr.p tex
  end;
  if Float.abs (Color.acc_luminance tr) <= bailout then Color.acc_set out c.ar c.ag c.ab
  else
    let w = weight *. Floats.fmax (Float.abs tr.ar) (Floats.fmax (Float.abs tr.ag) (Float.abs tr.ab)) in
    let rc = fr.rc in
    if eta = 1. then begin
      (* same index on both sides: straight through, no trace level used *)
      fr.k.child <- w;
      trace_ray s Ray.epsilon infinity fr.p d level fr.k (Interior.beyond inner media) rc;
      through out c tr fade rc
    end
    else
      let cos_i = -.dot d n in
      let k = 1. +. (eta *. eta *. ((cos_i *. cos_i) -. 1.)) in
      let rd = fr.rd in
      if k < 0. then begin
        (* total internal reflection: not filtered by the surface colour;
           iridescent by the top layer's finish, as POV-Ray's
           ComputeReflection makes it (its TIR passes the texture's
           finish) *)
        mirror d n n0 rd;
        fr.k.child <- weight;
        trace_ray (Scene.reflected s) Ray.epsilon infinity fr.p rd (level + 1) fr.k media rc;
        (match tex with
        | ({ tmap = None; finish = f; _ } : Texture.layer) :: _ when f.irid > 0. ->
            irid s f fr.p cos_i (Float.abs (dot rd n)) rc
        | _ -> ());
        Color.acc_set out (c.ar +. (fade.ar *. rc.ar)) (c.ag +. (fade.ag *. rc.ag)) (c.ab +. (fade.ab *. rc.ab))
      end
      else begin
        (* a top normal tilted away from the eye bends the ray about
           its opposite, as in POV-Ray *)
        let side = if cos_i < 0. then -1. else 1. in
        let m = side *. ((eta *. cos_i *. side) -. Float.sqrt k) in
        Vec3.set rd ((eta *. d.mx) +. (m *. n.mx)) ((eta *. d.my) +. (m *. n.my)) ((eta *. d.mz) +. (m *. n.mz));
        fr.k.child <- w;
        trace_ray s Ray.epsilon infinity fr.p rd (level + 1) fr.k (Interior.beyond inner media) rc;
        through out c tr fade rc
      end

(* Shade the layers of a texture top down, adding into [acc]; [w] is what
   the layers above let through, and holds at the end what the whole
   texture lets through; sets the frame's top normal to the top layer's.
   [refl]: add the finishes' reflection (POV-Ray leaves it out where the
   light passing through is totally reflected inside: the TIR ray stands
   for it). A function of its own, not a closure in [shade]: it runs for
   every hit. The textures' patterns are taken at [tp]: the hit point,
   or in a texture map's entry the point its pattern passed on (see
   {!Texture.blend_m}). *)
and layers s d level media (fr : frame) refl (acc : Color.acc) (w : Color.acc) (tp : Vec3.m) = function
  | [] -> ()
  | (layer : Texture.layer) :: rest -> (
      (* set again for each layer: rays traced for the layers above
         shaded other surfaces *)
      if fr.has_uv then Pattern.set_uv fr.uv.mx fr.uv.my;
      match layer.tmap with
      | Some m ->
          (* a patterned layer: blend the textures around the value *)
          let lv = tmap_enter () in
          let pk = lv.pick and c = lv.c and f = lv.f in
          Texture.blend_m m tp pk;
          let framed =
            (match m.kind with Texture.Field _ -> false | Texture.Map | Texture.Average -> true)
            && not (Transform.is_identity m.frame)
          in
          if framed then chain_push fr m.frame;
          Color.acc_set c 0. 0. 0.;
          Color.acc_set f 0. 0. 0.;
          for j = 0 to pk.n - 1 do
            let c' = lv.c1 and f' = lv.f1 in
            Color.acc_set c' 0. 0. 0.;
            Color.acc_set f' 1. 1. 1.;
            layers s d level media fr refl c' f' pk.tp (Texture.entry m pk j);
            let k = Texture.weight m pk j in
            Color.acc_set c (c.ar +. (k *. c'.ar)) (c.ag +. (k *. c'.ag)) (c.ab +. (k *. c'.ab));
            Color.acc_set f (f.ar +. (k *. f'.ar)) (f.ag +. (k *. f'.ag)) (f.ab +. (k *. f'.ab))
          done;
          Color.acc_set acc (acc.ar +. (w.ar *. c.ar)) (acc.ag +. (w.ag *. c.ag)) (acc.ab +. (w.ab *. c.ab));
          Color.acc_set w (w.ar *. f.ar) (w.ag *. f.ag) (w.ab *. f.ab);
          if framed then fr.nchain <- fr.nchain - 1;
          tmap_leave ();
          if not (Color.acc_is_black w) then layers s d level media fr refl acc w tp rest
      | None ->
          let p = fr.p and n0 = fr.n0 in
          let n =
            match layer.normal with
            | None -> n0
            | Some nm ->
                (* kept as it is where it tilts away from the eye, as in
                   POV-Ray: the lights in front of the surface then miss
                   it, and [mirror] mends the rays it reflects *)
                let pn = fr.pn in
                Normal.perturb_through nm tp n0 fr.chain fr.nchain fr.tn pn;
                pn
          in
          if not fr.top_set then begin
            fr.top_set <- true;
            Vec3.set fr.top n.mx n.my n.mz
          end;
          let f = layer.finish in
          let pig = fr.pig in
          Pigment.into layer.pigment tp pig;
          let pc = pig in
          let k = fr.k in
          fr.a.alpha <-
            (if s.Scene.settings.legacy_alpha then
               1. -. ((pig.filter *. Floats.fmax pc.r (Floats.fmax pc.g pc.b)) +. pig.transmit)
             else 1. -. pig.filter -. pig.transmit);
          let alpha = fr.a.alpha in
          (* the radiosity first: its gather rays shade other surfaces *)
          (match s.settings.radiosity with None -> () | Some r -> radiosity_term s r level media fr f w n);
          (* this layer's own colour: lights, then ambient (or the
             radiosity) and emission *)
          let dl = fr.dl in
          Color.acc_set dl 0. 0. 0.;
          (* shadow rays start in the interiors this ray runs in (set
             here: the rays traced above shaded other hits) *)
          let sw = Direct.walk fr.sh in
          Shadow.starts_in sw media;
          (* with photons, a target that refracts them casts a full
             shadow here: its light comes as photons *)
          Shadow.collects sw fr.collect;
          Direct.lights s fr.sh fr.lights f pc fr.a p n d dl;
          (if fr.collect && (f.diffuse <> 0. || f.diffuse_back <> 0. || f.specular <> 0. || f.phong <> 0.) then
             match s.settings.photons with
             | Some { state = { map = Some m }; _ } -> Direct.photons s m fr.sh f pc fr.a p n fr.n0 d dl
             | _ -> ());
          let amb =
            match s.settings.radiosity with
            | None -> s.settings.ambient_light
            | Some r ->
                if Radiosity.depth () < r.recursion_limit then begin
                  (* POV-Ray 3.7: diffuse x pigment x the light gathered *)
                  let a = fr.amb and k = alpha *. f.diffuse in
                  Color.acc_set dl (dl.ar +. (k *. pc.r *. a.ar)) (dl.ag +. (k *. pc.g *. a.ag)) (dl.ab +. (k *. pc.b *. a.ab))
                end;
                (* ambient only in scenes older than 3.7 *)
                if r.keep_ambient then s.settings.ambient_light else Color.black
          in
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
          (* the layers above filter this layer's own colour, not its
             reflection: POV-Ray adds each layer's reflected ray as it
             is (trace.cpp's ComputeLightedTexture; measured: a mirror
             under an rgbt 0.5 layer reflects in full) *)
          let lr = w.ar *. lr and lg = w.ag *. lg and lb = w.ab *. lb in
          let lr = if refl_here then lr +. rc.ar else lr
          and lg = if refl_here then lg +. rc.ag else lg
          and lb = if refl_here then lb +. rc.ab else lb in
          Color.acc_set acc (acc.ar +. lr) (acc.ag +. lg) (acc.ab +. lb);
          Color.acc_set w
            (w.ar *. ((pig.filter *. pc.r) +. pig.transmit))
            (w.ag *. ((pig.filter *. pc.g) +. pig.transmit))
            (w.ab *. ((pig.filter *. pc.b) +. pig.transmit));
          if f.conserve_energy && Finish.has_reflection f then begin
            (* POV-Ray's conserve_energy: what the layer lets through
               less what it reflects (1 - reflectivity, at most 1 per
               channel); its reflectivity also where the reflection is
               not traced (totally reflected inside) *)
            if not refl_here then reflectivity f pc n d fr;
            let kr = fr.kr in
            Color.acc_set w
              (w.ar *. Floats.fmin 1. (1. -. kr.ar))
              (w.ag *. Floats.fmin 1. (1. -. kr.ag))
              (w.ab *. Floats.fmin 1. (1. -. kr.ab))
          end;
          if not (Color.acc_is_black w) then layers s d level media fr refl acc w tp rest)

(* POV-Ray's radiosity at the frame's point, into [fr.amb], once per
   hit and only where the recursion depth allows it and it can show (the
   layer's greatest possible share over the ADC bailout, as POV-Ray
   tests it) *)
and radiosity_term s (r : Radiosity.t) level media (fr : frame) (f : Finish.t) (w : Color.acc) (n : Vec3.m) =
  if (not fr.amb_done) && Radiosity.depth () < r.recursion_limit then begin
    let pc = fr.pig in
    let most =
      Color.grey (w.ar *. pc.r) (w.ag *. pc.g) (w.ab *. pc.b) *. fr.a.alpha *. f.diffuse
    in
    if most > s.Scene.settings.adc_bailout then begin
      fr.amb_done <- true;
      (* the error bound: lowered by low_error_factor in the pretrace,
         raised for points that weigh little, doubled per depth (passed
         in the domain's sums: as an argument it would be boxed) *)
      let weight = fr.k.weight *. most in
      let eb = r.error_bound *. if Radiosity.final r.cache then 1. else r.low_error_factor in
      let eb = if weight < 0.25 then eb +. (0.25 -. weight) else eb in
      (Radiosity.sums ()).eb <- Float.ldexp eb (Radiosity.depth ());
      ambient s r level media fr (if r.normal then n else fr.n0)
    end
  end

(* POV-Ray's ComputeAmbient: the records of the cache that serve the
   point (the error bound lowered by low_error_factor in the pretrace,
   raised for points that weigh little, doubled per depth); enough of
   them (any in the final pass, unless always_sample), or a gather,
   blended with what was found; then made grey by gray_threshold and
   scaled by brightness *)
and ambient s (r : Radiosity.t) level media (fr : frame) (nrm : Vec3.m) =
  let c = r.cache in
  let depth = Radiosity.depth () in
  let filling = Radiosity.filling c and final = Radiosity.final c in
  let a = fr.amb in
  let sm = Radiosity.sums () in
  Radiosity.lookup c depth fr.p nrm sm a;
  let reuse = sm.ws in
  if not (4. *. reuse >= float_of_int (Radiosity.reuse_count r depth) || (final && (not r.always_sample) && reuse > 0.))
  then begin
    let fr_ = a.ar and fg = a.ag and fb = a.ab in
    gather s r level media fr nrm filling;
    if reuse > 0. then begin
      let k = 1. /. (reuse +. 1.) in
      Color.acc_set a (k *. ((fr_ *. reuse) +. a.ar)) (k *. ((fg *. reuse) +. a.ag)) (k *. ((fb *. reuse) +. a.ab))
    end
  end;
  let gr = r.gray_threshold and b = r.brightness in
  let grey = gr *. Color.grey a.ar a.ag a.ab and k = 1. -. gr in
  Color.acc_set a (b *. ((k *. a.ar) +. grey)) (b *. ((k *. a.ag) +. grey)) (b *. ((k *. a.ab) +. grey))

(* The light gathered over the hemisphere about [nrm] at the frame's
   point, into [fr.amb]: the mean of [Radiosity.rays] rays in
   cosine-weighted directions (a stratified set turned by numbers of the
   point's own, so that a render does not depend on the domains), each
   tracing what radiosity's rays see one recursion deeper, its light
   limited to max_sample (POV-Ray's GatherLight). With [keep], the
   gather is kept in the cache, its reach the harmonic mean distance of
   what the rays met, within minimum_reuse and maximum_reuse of the
   distance to the camera (doubled per depth). *)
and gather s (r : Radiosity.t) _level media (fr : frame) (nrm : Vec3.m) keep =
  let depth = Radiosity.depth () in
  let count = Radiosity.rays r depth in
  let g = Scene.radiosity s in
  let p = fr.p in
  let sm = Scratch.get gather_key in
  let key =
    Sampler.hash
      (Int64.to_int (Int64.bits_of_float p.mx)
      lxor Sampler.hash (Int64.to_int (Int64.bits_of_float p.my) lxor Sampler.hash (Int64.to_int (Int64.bits_of_float p.mz))))
  in
  Sampler.reset sm ~seed:(7919 + depth) ~pixel:key ~sample:0;
  let r1 = Sampler.get sm 0 and r2 = Sampler.get sm 1 in
  let lvl = Int.min (Radiosity.trace_level depth) g.settings.max_trace_level in
  let wt = Radiosity.weight r depth in
  let rd = fr.rd and rc = fr.rc and sum = fr.amb in
  Color.acc_set sum 0. 0. 0.;
  let inv = ref 0. and near = ref infinity and tx = ref 0. and ty = ref 0. and tz = ref 0. in
  Radiosity.descend ();
  for i = 0 to count - 1 do
    Radiosity.direction_into nrm i count r1 r2 rd;
    fr.k.child <- wt;
    trace_ray g Ray.epsilon infinity p rd lvl fr.k media rc;
    let dist = fr.k.dist in
    inv := !inv +. (1. /. dist);
    if dist < !near then begin
      near := dist;
      tx := rd.mx;
      ty := rd.my;
      tz := rd.mz
    end;
    let m = Floats.fmax rc.ar (Floats.fmax rc.ag rc.ab) in
    let k = if r.max_sample > 0. && m > r.max_sample then r.max_sample /. m else 1. in
    Color.acc_set sum (sum.ar +. (k *. rc.ar)) (sum.ag +. (k *. rc.ag)) (sum.ab +. (k *. rc.ab))
  done;
  Radiosity.ascend ();
  let k = 1. /. float_of_int count in
  Color.acc_set sum (k *. sum.ar) (k *. sum.ag) (k *. sum.ab);
  if keep then begin
    let cam = s.Scene.camera.location in
    let ex = cam.x -. p.mx and ey = cam.y -. p.my and ez = cam.z -. p.mz in
    let to_eye = Float.sqrt ((ex *. ex) +. (ey *. ey) +. (ez *. ez)) in
    let lo = Float.ldexp (to_eye *. r.minimum_reuse) depth and hi = Float.ldexp (to_eye *. r.maximum_reuse) depth in
    (* nearly touching two surfaces: the rays may be unsound, not kept *)
    if !near > hi *. 0.0001 then begin
      let hmd = Float.min hi (Float.max lo (float_of_int count /. !inv)) in
      Radiosity.add r.cache depth
        { px = p.mx; py = p.my; pz = p.mz; nx = nrm.mx; ny = nrm.my; nz = nrm.mz; ir = sum.ar; ig = sum.ag; ib = sum.ab;
          hmd; near = !near; tx = !tx; ty = !ty; tz = !tz }
        (Float.ldexp (hmd *. r.error_bound) depth +. 0.25 *. hmd *. Float.ldexp 1. depth)
    end
  end

(* POV-Ray's reflectivity of a finish seen along [d] about [n] (trace.cpp's
   ComputeReflectivity, then the reflection's metallic tint by the
   pigment [pc]), per channel, into [fr.kr]; the weight its reflected ray
   is traced with into [fr.k.child], relative to the layer's *)
and reflectivity (f : Finish.t) (pc : Pigment.out) (n : Vec3.m) (d : Vec3.m) (fr : frame) =
  let rf = f.reflection in
  let cos_i = -.dot d n in
  (* kr = rmin + k (rmax - rmin), per channel, in scalars *)
  let lo = rf.rmin and hi = rf.rmax in
  let k =
    if rf.fresnel then
      let r = fr.k.fres in
      if r = 1. then 0. else Finish.fresnel r cos_i
    else Float.pow (1. -. cos_i) rf.falloff
  in
  let kr = lo.r +. (k *. (hi.r +. (-1. *. lo.r)))
  and kg = lo.g +. (k *. (hi.g +. (-1. *. lo.g)))
  and kb = lo.b +. (k *. (hi.b +. (-1. *. lo.b))) in
  fr.k.child <-
    (if rf.fresnel then Floats.fmax kr (Floats.fmax kg kb) else Floats.fmax (max_channel lo) (max_channel hi));
  let m = rf.rmetallic in
  let mk = if m = 0. then 0. else Finish.metallic_k m cos_i in
  Color.acc_set fr.kr (kr *. Finish.tint m mk pc.r) (kg *. Finish.tint m mk pc.g) (kb *. Finish.tint m mk pc.b)

(* the reflected light into [out] (the frame's [rf]); the reflected ray
   starts at the frame's point along its [rd], weighs [fr.k.refl] times
   the reflection's, and brings its light back into its [rc] *)
and reflection s (f : Finish.t) (pc : Pigment.out) (n : Vec3.m) (d : Vec3.m) level media (fr : frame) (out : Color.acc) =
  if not (Finish.has_reflection f) then Color.acc_set out 0. 0. 0.
  else begin
    reflectivity f pc n d fr;
    let kr = fr.kr.ar and kg = fr.kr.ag and kb = fr.kr.ab in
    if kr = 0. && kg = 0. && kb = 0. then Color.acc_set out 0. 0. 0.
    else begin
      let rf = f.reflection in
      let rd = fr.rd and rc = fr.rc in
      mirror d n fr.n0 rd;
      fr.k.child <- fr.k.refl *. fr.k.child;
      (* no_reflection objects are left out from here on *)
      trace_ray (Scene.reflected s) Ray.epsilon infinity fr.p rd (level + 1) fr.k media rc;
      if f.irid > 0. then irid s f fr.p (-.dot d n) (Float.abs (dot rd n)) rc;
      if rf.exponent = 1. then Color.acc_set out (kr *. rc.ar) (kg *. rc.ag) (kb *. rc.ab)
      else
        let e = 1. /. rf.exponent in
        Color.acc_set out (kr *. Float.pow rc.ar e) (kg *. Float.pow rc.ag e) (kb *. Float.pow rc.ab e)
    end
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

(* the radiance along [r] into [out], from hits nearer than [far] *)
let trace_camera_ray s far (r : camera_ray) out =
  Scratch.reset (Scratch.get frames_key);
  if s.Scene.settings.radiosity <> None then Radiosity.reset_depth ();
  (* no_image objects are left out of what camera rays (and rays refracted
     from them) see *)
  trace_ray (Scene.image s) 0. far r.o r.d 1 r.k (start_media s r.o) out

let trace s (ray : Ray.t) =
  let r = Scratch.get camera_key in
  Vec3.load r.o ray.origin;
  Vec3.load r.d ray.dir;
  trace_camera_ray s infinity r r.light;
  Color.of_acc r.light

(* Focal blur (an aperture and blur_samples given): lens rays are traced
   in batches until there are blur_samples of them or the variance of
   the mean of every channel is under the camera's threshold for that
   count (POV-Ray's confidence test, with its batch sizes: 7, 6, 6, 4, 4,
   4, 4, 2 from 37 samples, 7, 6, 6 from 19, 7 from 7, then 4 at a time).
   The lens points are the camera's (a centre and a hexagon first, each
   prefix spread evenly over the lens) turned by an angle of the pixel's
   own. POV-Ray jitters the points of a fixed hexagonal grid: blurred
   parts agree in the mean, not pixel for pixel. *)
let hex4 = [| 7; 6; 6; 4; 4; 4; 4; 2 |] and hex3 = [| 7; 6; 6 |] and hex2 = [| 7 |]

(* the size of batch [level] for [n] samples *)
let batch n level =
  let sizes = if n >= 37 then hex4 else if n >= 19 then hex3 else if n >= 7 then hex2 else [||] in
  if level < Array.length sizes then sizes.(level) else 4

(* per domain: the lens points' sampler, the sums of the rays' light and
   of its squares *)
let blur_key = Scratch.key (fun () -> (Sampler.create ~seed:0 ~pixel:0 ~sample:0, Color.acc 0., Color.acc 0.))

(* whether the variance of the mean of [n] rays is under [limit] in
   every channel *)
let[@inline] variance_of_mean s q k = ((q *. k) -. (s *. k *. (s *. k))) *. k

let settled (sum : Color.acc) (sq : Color.acc) n limit =
  let k = 1. /. float_of_int n in
  variance_of_mean sum.ar sq.ar k < limit
  && variance_of_mean sum.ag sq.ag k < limit
  && variance_of_mean sum.ab sq.ab k < limit

(* for the image point in [r.at] (its camera coordinates in [r.cam]): read
   from the record, the four coordinates passed would be boxed *)
let focal_blur_into (s : Scene.t) (r : camera_ray) out =
  let px = r.at.mx and py = r.at.my and sx = r.cam.mx and sy = r.cam.my in
  let cam = s.camera in
  let n = cam.blur_samples in
  let key = (int_of_float (Float.floor py) * 65599) + int_of_float (Float.floor px) in
  let sampler, sum, sq = Scratch.get blur_key in
  Sampler.reset sampler ~seed:0 ~pixel:key ~sample:0;
  (* the points turned by an angle of the pixel's own *)
  let phi = 2. *. Float.pi *. Sampler.get sampler 0 in
  let c = Float.cos phi and sn = Float.sin phi in
  Color.acc_set sum 0. 0. 0.;
  Color.acc_set sq 0. 0. 0.;
  let k = ref 0 and level = ref 0 and fin = ref false in
  while not !fin do
    let stop = min n (!k + batch n !level) in
    incr level;
    while !k < stop do
      let x = cam.blur_points.(2 * !k) and y = cam.blur_points.((2 * !k) + 1) in
      (* a point the camera sends no ray through stays black, as in POV-Ray *)
      if Camera.disc_into cam sx sy ((c *. x) -. (sn *. y)) ((sn *. x) +. (c *. y)) r.o r.d then
        trace_camera_ray s infinity r r.light
      else Color.acc_set r.light 0. 0. 0.;
      let l = r.light in
      Color.acc_set sum (sum.ar +. l.ar) (sum.ag +. l.ag) (sum.ab +. l.ab);
      Color.acc_set sq (sq.ar +. (l.ar *. l.ar)) (sq.ag +. (l.ag *. l.ag)) (sq.ab +. (l.ab *. l.ab));
      incr k
    done;
    fin := !k >= n || (!k >= cam.blur_samples_min && settled sum sq !k cam.blur_thresholds.(!k - 1))
  done;
  let w = 1. /. float_of_int !k in
  Color.acc_set out (w *. sum.ar) (w *. sum.ag) (w *. sum.ab)

(* A mesh camera (POV-Ray's mesh_camera) at the image point in [r.at]:
   the mean of the rays it shoots there, black where it shoots none (as
   POV-Ray's TracePixel divides by the rays traced) *)
let mesh_camera_into (s : Scene.t) m ~width ~height (r : camera_ray) out =
  let sr = ref 0. and sg = ref 0. and sb = ref 0. and n = ref 0 in
  for k = 0 to Mesh_camera.rays m - 1 do
    Vec3.set r.o r.at.mx r.at.my 0.;
    if Mesh_camera.ray_into m ~width ~height k r.o r.d then begin
      trace_camera_ray s (Mesh_camera.far m) r r.light;
      let l = r.light in
      sr := !sr +. l.ar;
      sg := !sg +. l.ag;
      sb := !sb +. l.ab;
      incr n
    end
  done;
  if !n = 0 then Color.acc_set out 0. 0. 0.
  else
    let k = float_of_int !n in
    Color.acc_set out (!sr /. k) (!sg /. k) (!sb /. k)

(* The light through the image point [(px, py)] into [out]; inlined:
   the coordinates stay unboxed. *)
let[@inline] sample_in (s : Scene.t) ~width ~height px py out =
  let sx = Camera.pixel_x ~width px and sy = Camera.pixel_y ~height py in
  let cam = s.camera in
  let r = Scratch.get camera_key in
  match cam.projection with
  | Camera.Mesh m ->
      (* no focal blur: POV-Ray's mesh camera does not jitter its rays *)
      Vec3.set r.at px py 0.;
      mesh_camera_into s m ~width ~height r out
  | _ ->
      if cam.aperture <> 0. && cam.blur_samples > 0 then begin
        Vec3.set r.at px py 0.;
        Vec3.set r.cam sx sy 0.;
        focal_blur_into s r out
      end
      else if Camera.ray_into cam sx sy r.o r.d then trace_camera_ray s infinity r out
      else Color.acc_set out 0. 0. 0.

let sample_into s ~width ~height px py out = sample_in s ~width ~height px py out

let sample s ~width ~height px py =
  let out = Color.acc 0. in
  sample_in s ~width ~height px py out;
  Color.of_acc out

let pixel_into (s : Scene.t) ~width ~height x y out =
  match s.settings.radiosity with
  | Some r when Radiosity.picture_into r.cache ~width ~height x y out -> ()
  | _ -> sample_in s ~width ~height (float_of_int x +. 0.5) (float_of_int y +. 0.5) out

let pixel s ~width ~height x y =
  let out = Color.acc 0. in
  pixel_into s ~width ~height x y out;
  Color.of_acc out

(* Indices below 2^27 in increasing [rank] (0 to 63), each rank's in an
   order of their own: by a hash of the index *)
let hashed ?(rank = fun _ -> 0) is =
  let key = Array.map (fun i -> (rank i lsl 55) lor ((Sampler.hash i land 0xfff_ffff) lsl 27) lor i) is in
  Array.sort Int.compare key;
  Array.map (fun k -> k land 0x7ff_ffff) key

(* The pixels of a [width] x [height] image, as indices [y * width + x],
   coarse to fine: those on every 2^k-th row and column before the
   others, the largest k first; those of a k > 0 in an order of their
   own (by a hash of the index), so that pixels taken one after the
   other lie far apart and a batch of them traced ahead seldom makes a
   record another one of the batch would have used; the others (one or
   both coordinates odd: three pixels in four, most served by the
   records of the pixels before them) by rows, the pixels after one
   another near one another, as fast to trace as a picture's rows.
   Radiosity2.pov at 320x240 on 2 domains, batches of 64: traced again,
   1 pixel in 8 taken all by rows, 1 in 2500 all by the hash, 1 in 66
   this way; on one domain, some 25% slower all by the hash than by
   rows, this way as fast as by rows. *)
let centres_order ~width ~height =
  let n = width * height in
  let rec zeros v k = if v land 1 = 1 then k else zeros (v lsr 1) (k + 1) in
  let coarseness i =
    let x = i mod width and y = i / width in
    Int.min (if x = 0 then 62 else zeros x 0) (if y = 0 then 62 else zeros y 0)
  in
  let coarse = ref [] and fine = ref [] in
  for i = n - 1 downto 0 do
    if coarseness i = 0 then fine := i :: !fine else coarse := i :: !coarse
  done;
  Array.append (hashed ~rank:(fun i -> 62 - coarseness i) (Array.of_list !coarse)) (Array.of_list !fine)

(* a sample traced ahead's colour, per domain *)
let ahead_key = Scratch.key (fun () -> Color.acc 0.)

(* Radiosity's samples, the points [(xs.(i), ys.(i))], traced each after
   the ones before it, their colours given to [take i] in turn: on the
   calling domain, or with [par] in batches (of 2 up to [batch], grown
   while hardly any of a batch is traced again: while the cache is empty,
   every sample traced ahead gathers, and in turn few do), each traced
   ahead on every domain, then taken in turn, a sample whose lookups a
   record taken before it in the batch weighs in traced again, in turn,
   as is one abandoned for its many lookups (see Radiosity's
   speculate). The cache, and the colours, are the same. *)
let in_turn (s : Scene.t) c ?par ~width ~height ~batch xs ys take =
  let n = Float.Array.length xs in
  let out = Color.acc 0. in
  match par with
  | None ->
      for i = 0 to n - 1 do
        sample_in s ~width ~height (Float.Array.get xs i) (Float.Array.get ys i) out;
        take i out
      done
  | Some par ->
      let b = Radiosity.batch () in
      (* per place in the batch: traced ahead (not abandoned), what was
         found, the colour *)
      let ahead = Array.make batch false
      and found = Array.init batch (fun _ -> Radiosity.outcome ())
      and colours = Float.Array.make (3 * batch) 0. in
      let trace ~ahead i k out =
        Radiosity.begin_sample ~ahead ();
        sample_in s ~width ~height (Float.Array.get xs i) (Float.Array.get ys i) out;
        Radiosity.end_sample found.(k)
      in
      let lo = ref 0 and size = ref (Int.min 2 batch) in
      while !lo < n do
        let m = Int.min !size (n - !lo) in
        let again = ref 0 in
        Radiosity.speculate c true;
        Fun.protect
          ~finally:(fun () -> Radiosity.speculate c false)
          (fun () ->
            par m (fun k ->
                let a = Scratch.get ahead_key in
                match trace ~ahead:true (!lo + k) k a with
                | () ->
                    ahead.(k) <- true;
                    Color.acc_store colours k a
                | exception Radiosity.Abandoned -> ahead.(k) <- false);
            Radiosity.start_batch b;
            for k = 0 to m - 1 do
              if ahead.(k) && not (Radiosity.conflicts b found.(k)) then Color.acc_load colours k out
              else begin
                incr again;
                trace ~ahead:false (!lo + k) k out
              end;
              Radiosity.commit c b found.(k);
              take (!lo + k) out
            done);
        lo := !lo + m;
        (* the next batch twice as large while at most 1 in 64 is traced
           again, half as large when over 1 in 32 are (cornell.pov at
           160x120 on 2 domains, three runs each: traced ahead in vain
           0.62 to 0.92 s, then again in turn 0.52 to 0.77 s, with 1 in
           8 and 1 in 4; 0.40 to 0.47 s and 0.33 to 0.38 s this way) *)
        if 64 * !again <= m then size := Int.min batch (2 * !size)
        else if 32 * !again > m then size := Int.max 2 (!size / 2)
      done

(* POV-Ray's radiosity pretrace: camera rays through the centres of
   blocks of [pretrace_start] of the image's width, then of half that,
   down to [pretrace_end] (at least a pixel), their gathers kept in the
   cache; then its final pass, as far as its gathers go: every pixel's
   centre, by the final rules, a record kept where none serves (POV-Ray
   keeps those its final pass makes, so that the pixels after reuse
   them), the colour found the pixel's. Each sample is traced after the
   ones before it (with [par], on several domains at once, to the same
   cache and colours: see [in_turn]), so the picture does not depend on
   the domains. *)
let prepare ?par ?(batch = 128) ?(progress = fun ~done_:_ ~total:_ -> ()) (s : Scene.t) ~width ~height =
  (* the photons first: radiosity's gathers see them *)
  Caustics.prepare ?par s;
  match s.settings.radiosity with
  | None -> ()
  | Some r ->
      (* the orders below number pixels and blocks in 27 bits *)
      if width * height > 1 lsl 27 then invalid_arg "Whitted.prepare: more than 2^27 pixels";
      let c = r.cache in
      Radiosity.clear c;
      Radiosity.set_filling c true;
      Radiosity.set_final c false;
      Fun.protect
        ~finally:(fun () ->
          Radiosity.speculate c false;
          Radiosity.set_filling c false;
          Radiosity.set_final c true)
        (fun () ->
          let stop = Float.max 1. (r.pretrace_end *. float_of_int width) in
          let xs = ref [] and ys = ref [] in
          let rec pass size =
            let size = Float.max 1. size in
            let nx = int_of_float (Float.ceil (float_of_int width /. size))
            and ny = int_of_float (Float.ceil (float_of_int height /. size)) in
            (* a pass's blocks in an order of their own (by a hash of
               the index), as the final pass's coarse pixels *)
            Array.iter
              (fun k ->
                let i = k mod nx and j = k / nx in
                xs := Float.min (float_of_int width -. 0.5) ((float_of_int i +. 0.5) *. size) :: !xs;
                ys := Float.min (float_of_int height -. 0.5) ((float_of_int j +. 0.5) *. size) :: !ys)
              (hashed (Array.init (nx * ny) Fun.id));
            if size > stop *. 1.0001 then pass (size /. 2.)
          in
          pass (r.pretrace_start *. float_of_int width);
          let points l = Float.Array.of_list (List.rev l) in
          let passes = List.length !xs in
          let total = passes + (width * height) in
          in_turn s c ?par ~width ~height ~batch (points !xs) (points !ys) (fun i _ ->
              if i land 255 = 255 then progress ~done_:(i + 1) ~total);
          Radiosity.set_final c true;
          let order = centres_order ~width ~height in
          let centre k = float_of_int k +. 0.5 in
          let picture = Float.Array.make (3 * width * height) 0. in
          in_turn s c ?par ~width ~height ~batch
            (Float.Array.init (width * height) (fun i -> centre (order.(i) mod width)))
            (Float.Array.init (width * height) (fun i -> centre (order.(i) / width)))
            (fun i (a : Color.acc) ->
              if i land 255 = 255 || i = (width * height) - 1 then progress ~done_:(passes + i + 1) ~total;
              Color.acc_store picture order.(i) a);
          Radiosity.set_picture c ~width ~height picture)
