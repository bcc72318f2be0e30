(* POV-Ray 3.7's photon shooting (its photonshootingtask and photons
   files, read for the rules): from each light that casts shadows, at
   each target, a grid of directions over the cone that holds the
   target's bounding sphere, spaced so that photons land [spacing] apart
   at the target (times its multiplier); each photon reflects and
   refracts where the surfaces and the light allow it, and is stored on
   every surface it meets after its first (and in the media it crosses,
   with media photons). Run once per scene before the render, the rings
   of directions in batches on every domain. *)

(* a target: a top-level object (a union's children apart, unless it
   says split_union off), the leaves that are its surfaces *)
type unit_ = { leaves : Object.t list; flags : Photon.flags; lo : Vec3.t; hi : Vec3.t }

let rec leaves (o : Object.t) acc =
  match o.geom with
  | Prim _ -> o :: acc
  | Union cs | Intersection cs | Merge cs -> Array.fold_right leaves cs acc

let first_target o = List.find_opt (fun (l : Object.t) -> l.photon.target > 0.) (leaves o [])

let rec units (o : Object.t) acc =
  match (o.geom, first_target o) with
  | _, None -> acc
  | Union cs, Some l when l.photon.split_union && Array.length o.clip = 0 -> Array.fold_right units cs acc
  | _, Some l -> (
      match o.bounds with
      | Some (lo, hi) when Vec3.is_finite lo && Vec3.is_finite hi ->
          { leaves = leaves o []; flags = l.photon; lo; hi } :: acc
      | _ -> acc)

let sphere u =
  let ctr = Vec3.scale 0.5 (Vec3.add u.lo u.hi) in
  (ctr, Vec3.dist ctr u.lo)

let parallel (l : Light.t) = match l.kind with Parallel _ | Cylinder _ -> true | Point | Spot _ -> false

let axis (l : Light.t) =
  match l.kind with
  | Parallel { point_at } | Cylinder { point_at; _ } | Spot { point_at; _ } ->
      Vec3.normalize (Vec3.sub point_at l.position)
  | Point -> Vec3.unit_z

(* POV-Ray's count: the spacing that would shoot about that many photons
   at the targets (their bounding spheres, the words they say) *)
let spacing_for_count (s : Scene.t) (ps : Photon.settings) us =
  let estimate =
    Array.fold_left
      (fun acc (light : Light.t) ->
        if light.shadowless then acc
        else
          List.fold_left
            (fun acc u ->
              if not (Photon.shoots u.flags ~light:light.photons) then acc
              else
                let _, rad = sphere u in
                let x = Float.pi *. ((rad /. (u.flags.target *. ps.spacing)) ** 2.) in
                let rfl = Photon.merged u.flags.reflection light.photons.reflection
                and rfr = Photon.merged u.flags.refraction light.photons.refraction in
                let x = if rfl && rfr then 1.5 *. x else x in
                let x = if u.flags.collect then (if rfl && rfr then 3. *. x else if rfr then 2. *. x else x) else x in
                acc +. (0.5 *. x))
            acc us)
      0. s.lights
  in
  if estimate > 0. then ps.spacing *. Float.sqrt (estimate /. float_of_int ps.count) else ps.spacing

(* what one photon meets; its state (the objects it sees are its
   [view]: without the no_image objects from the light and after
   refractions, without the no_reflection ones after a reflection, as
   camera rays) *)
type shot = {
  light : Light.t;
  unit_ : unit_;
  spread : float;
  par : bool;
  max_level : int;
  adc : float;
  st : Photon.store;
  mst : Photon.store;  (** the media's photons *)
  mutable hit_target : bool;
  pig : Pigment.out;
  rng : Random.State.t;
  ps : Photon.settings;
}

let grey r g b = (0.297 *. r) +. (0.589 *. g) +. (0.114 *. b)
let max3 r g b = Float.max r (Float.max g b)

(* a layer's reflection as a photon sees it *)
type mirror = { kr : Color.t; w : float; n : Vec3.t; expo : float }

let reflectivity (f : Finish.t) (pc : Pigment.out) fres cos_i =
  let rf = f.reflection in
  let lo = rf.rmin and hi = rf.rmax in
  let k =
    if rf.fresnel then if fres = 1. then 0. else Finish.fresnel fres cos_i else Float.pow (1. -. cos_i) rf.falloff
  in
  let ch a b = a +. (k *. (b -. a)) in
  let m = rf.rmetallic in
  let mk = if m = 0. then 0. else Finish.metallic_k m cos_i in
  let kr =
    Color.make (ch lo.r hi.r *. Finish.tint m mk pc.r) (ch lo.g hi.g *. Finish.tint m mk pc.g)
      (ch lo.b hi.b *. Finish.tint m mk pc.b)
  in
  let w =
    if rf.fresnel then max3 (ch lo.r hi.r) (ch lo.g hi.g) (ch lo.b hi.b)
    else Float.max (max3 lo.r lo.g lo.b) (max3 hi.r hi.g hi.b)
  in
  (kr, w)

let reflect d n = Vec3.sub d (Vec3.scale (2. *. Vec3.dot d n) n)

(* the mirror direction about [n], mended where it would go below the
   raw surface [n0] (as camera rays are) *)
let mirror d n n0 =
  let r = reflect d n in
  if Vec3.dot r n0 < 0. then reflect d n0 else r

let rec trace sh view (o : Vec3.t) (d : Vec3.t) (c : Color.t) weight level depth passprev media =
  if level < sh.max_level && weight >= sh.adc then begin
    let level = level + 1 in
    match next_hit view o d with
    | None -> ()
    | Some (h : Scene.hit) ->
        let obj = h.obj and fl = h.obj.photon in
        let gate = level = 1 || passprev in
        let through =
          if not gate then Some false
          else if fl.target > 0. && List.memq obj sh.unit_.leaves then begin
            sh.hit_target <- true;
            Some false
          end
          else if fl.pass_through then Some true
          else None
        in
        (match through with
        | None -> ()
        | Some pass -> surface sh view o h d c weight level depth passprev pass media)
  end

(* the nearest surface a photon meets: no_shadow objects are not seen *)
and next_hit s o d =
  match Scene.intersect s (Ray.make o d) Ray.epsilon infinity with
  | Some h when h.obj.no_shadow -> (
      match next_hit s h.point d with Some h' -> Some { h' with t = h.t +. h'.t } | None -> None)
  | r -> r

and surface sh view o (h : Scene.hit) d c weight level depth passprev pass media =
  let obj = h.obj and p = h.point in
  let inner = obj.interior in
  let dist = h.t in
  (* the media on the way here: photons left in them, and their extinction *)
  let c = if List.exists (fun (i : Interior.t) -> i.media <> []) media then stretch sh o d dist c depth level passprev media else c in
  (* interior fade over the way inside *)
  let c =
    if Interior.fades_light inner && List.memq inner media then
      let fc = inner.fade_color in
      Color.make
        (c.r *. Interior.fade_channel inner fc.r dist)
        (c.g *. Interior.fade_channel inner fc.g dist)
        (c.b *. Interior.fade_channel inner fc.b dist)
    else c
  in
  let depth = depth +. dist in
  if level > 1 && (not passprev) && obj.photon.collect then store sh p d c depth;
  let entering = Vec3.dot h.normal d < 0. in
  let n0 = if entering then h.normal else Vec3.neg h.normal in
  let tex = if entering then obj.texture else obj.back in
  let fres = Interior.fresnel_ior inner media in
  layers sh view h d c weight level depth pass media n0 fres 1. tex

(* a texture's layers at the hit, carrying [share] of the photon (a
   texture map splits it among its entries) *)
and layers sh view h d c weight level depth pass media n0 fres share tex =
  let p = Vec3.m () in
  Vec3.load p h.point;
  let fil = ref (1., 1., 1.) and trans = ref 1. and mirrors = ref [] and top = ref None in
  let rec go = function
    | [] -> `Done
    | (l : Texture.layer) :: rest when !trans > sh.adc -> (
        match l.tmap with
        | Some m ->
            let pk = Texture.pick () in
            Texture.blend_m m p pk;
            let entries = List.init pk.n (fun j -> (Texture.weight m pk j, Texture.entry m pk j)) in
            `Split (entries, rest)
        | None ->
            let n =
              match l.normal with
              | None -> n0
              | Some nm ->
                  let nn = Vec3.m () and out = Vec3.m () in
                  Vec3.load nn n0;
                  Normal.perturb_m nm p nn out;
                  Vec3.of_m out
            in
            if !top = None then top := Some n;
            let pc = sh.pig in
            Pigment.into l.pigment p pc;
            let f = l.finish in
            let fr, fg, fb = !fil in
            let kr_opt =
              if Finish.has_reflection f then begin
                let kr, w = reflectivity f pc fres (-.Vec3.dot d n) in
                mirrors := { kr; w = weight *. !trans *. w; n; expo = f.reflection.exponent } :: !mirrors;
                Some kr
              end
              else None
            in
            let fr = fr *. ((pc.filter *. pc.r) +. pc.transmit)
            and fg = fg *. ((pc.filter *. pc.g) +. pc.transmit)
            and fb = fb *. ((pc.filter *. pc.b) +. pc.transmit) in
            let fr, fg, fb =
              match kr_opt with
              | Some kr when f.conserve_energy ->
                  (fr *. Float.min 1. (1. -. kr.r), fg *. Float.min 1. (1. -. kr.g), fb *. Float.min 1. (1. -. kr.b))
              | _ -> (fr, fg, fb)
            in
            fil := (fr, fg, fb);
            trans := Float.min 1. (Float.abs (grey fr fg fb));
            go rest)
    | _ -> `Done
  in
  match go tex with
  | `Split (entries, rest) ->
      (* the layers above filter what the map's entries get *)
      let fr, fg, fb = !fil in
      List.iter
        (fun (k, t) ->
          if k > 0. then
            layers sh view h d
              (Color.make (c.r *. fr) (c.g *. fg) (c.b *. fb))
              weight level depth pass media n0 fres (share *. k) (t @ rest))
        entries
  | `Done -> (
      let c = Color.scale share c in
      let fr, fg, fb = !fil in
      let top = Option.value ~default:n0 !top in
      let inner = h.obj.interior in
      let flags = h.obj.photon and lf = sh.light.photons in
      if pass then
        trace sh view h.point d (Color.make (c.r *. fr) (c.g *. fg) (c.b *. fb)) (weight *. max3 fr fg fb) level depth true
          (Interior.beyond inner media)
      else begin
        let tir = ref false in
        if Photon.refracts flags ~light:lf && !trans > sh.adc then begin
          let w' = weight *. max3 fr fg fb in
          let filtered = Color.make (c.r *. fr) (c.g *. fg) (c.b *. fb) in
          let eta = Interior.relative_ior inner media in
          if eta = 1. then trace sh view h.point d filtered w' level depth false (Interior.beyond inner media)
          else begin
            let cos_i = -.Vec3.dot d top in
            let k = 1. +. (eta *. eta *. ((cos_i *. cos_i) -. 1.)) in
            if k < 0. then begin
              tir := true;
              trace sh (Scene.reflected view) h.point (mirror d top n0) c weight level depth false media
            end
            else
              let rd = Vec3.add (Vec3.scale eta d) (Vec3.scale ((eta *. cos_i) -. Float.sqrt k) top) in
              trace sh view h.point (Vec3.normalize rd) filtered w' level depth false (Interior.beyond inner media)
          end
        end;
        if Photon.reflects flags ~light:lf && not !tir then
          List.iter
            (fun m ->
              let kr = m.kr in
              if not (kr.r = 0. && kr.g = 0. && kr.b = 0.) then begin
                let e = if m.expo = 1. then 1. else 1. /. m.expo in
                let ch k x = if e = 1. then k *. x else k *. Float.pow x e in
                trace sh (Scene.reflected view) h.point (mirror d m.n n0)
                  (Color.make (ch kr.r c.r) (ch kr.g c.g) (ch kr.b c.b))
                  (m.w *. max3 kr.r kr.g kr.b) level depth false media
              end)
            (List.rev !mirrors)
      end)

(* POV-Ray's media photons over the stretch of [ds] from [o] along [d]
   (photons.cpp's DepositMediaPhotons): after the photon's first surface,
   in hollow interiors, up to [media_steps] of them spaced [media_factor]
   spreads apart at the distance travelled, each with the colour the
   photon came in with (no extinction within the stretch, as POV-Ray)
   and a flux that makes their density the light's; the colour out
   dimmed by the mean extinction of the samples. A stretch too short for
   one sample leaves POV-Ray's photon without colour (0/0): so here. *)
and stretch sh (o : Vec3.t) (d : Vec3.t) ds c depth level passprev media =
  let ms = List.concat_map (fun (i : Interior.t) -> i.media) media in
  let scatters = List.exists (fun (m : Media.t) -> m.scattering <> None) ms in
  (* POV-Ray leaves none where every medium says collect off *)
  let collect = List.exists (fun (m : Media.t) -> m.collect) ms in
  let absorbs = List.exists (fun (m : Media.t) -> m.absorption <> Color.black) ms in
  if not (scatters || absorbs) then c
  else begin
    let pig = Pigment.out () and dens = Color.acc 0. and ext = Color.acc 0. and p = Vec3.m () in
    let od = Color.acc 0. in
    let extinction s =
      Vec3.set p (o.x +. (s *. d.x)) (o.y +. (s *. d.y)) (o.z +. (s *. d.z));
      Color.acc_set ext 0. 0. 0.;
      List.iter (fun m -> Media.add_extinction m p pig dens ext) ms;
      Color.acc_set od (od.ar +. (ext.ar *. ds)) (od.ag +. (ext.ag *. ds)) (od.ab +. (ext.ab *. ds))
    in
    let ps = sh.ps in
    let deposit = level > 1 && (not passprev) && ps.media_steps > 0 && List.for_all (fun (i : Interior.t) -> i.hollow) media in
    let n =
      if deposit then begin
        let base = if sh.par then sh.spread else sh.spread *. depth in
        let n0 = int_of_float (ds /. (base *. ps.media_factor)) in
        let n, f =
          if n0 <= ps.media_steps then (n0, ps.media_factor) else (ps.media_steps, ds /. (base *. float_of_int ps.media_steps))
        in
        for j = 0 to n - 1 do
          let u = Random.State.float sh.rng 1. in
          let d0 = (float_of_int j +. 0.5 +. (ps.jitter *. u) -. (0.5 *. ps.jitter)) /. float_of_int n in
          let s = d0 *. ds in
          extinction s;
          if scatters && collect then begin
            let dp = depth +. s in
            let k = f *. sh.spread *. (if sh.par then 1. else dp) *. fade_at sh.light dp *. sh.spread *. sh.spread
                    *. (if sh.par then 1. else dp *. dp) in
            Photon.add sh.mst p.mx p.my p.mz ~r:(k *. c.Color.r) ~g:(k *. c.g) ~b:(k *. c.b) (-.d.x) (-.d.y) (-.d.z)
          end
        done;
        n
      end
      else begin
        (* not a deposit: the extinction by ten samples *)
        for j = 0 to 9 do
          extinction ((float_of_int j +. 0.5) *. ds /. 10.)
        done;
        10
      end
    in
    if n = 0 then Color.black
    else
      let k = 1. /. float_of_int n in
      Color.make (c.r *. Float.exp (-.od.ar *. k)) (c.g *. Float.exp (-.od.ag *. k)) (c.b *. Float.exp (-.od.ab *. k))
  end

and fade_at (l : Light.t) depth =
  if l.fade_power > 0. && Float.abs l.fade_distance > 1e-10 then
    2. /. (1. +. Float.pow (depth /. l.fade_distance) l.fade_power)
  else 1.

(* a photon kept where it lands: its flux makes the density of photons
   around it give the light's own intensity (POV-Ray's spread^2 depth^2),
   faded as the light fades over the whole way *)
and store sh (p : Vec3.t) d c depth =
  let fade = fade_at sh.light depth in
  let k = fade *. sh.spread *. sh.spread *. if sh.par then 1. else depth *. depth in
  Photon.add sh.st p.x p.y p.z ~r:(k *. c.r) ~g:(k *. c.g) ~b:(k *. c.b) (-.d.x) (-.d.y) (-.d.z)

(* rotation of [v] by [a] about the unit axis [k] *)
let rotate v k a =
  let c = Float.cos a and s = Float.sin a in
  Vec3.add
    (Vec3.add (Vec3.scale c v) (Vec3.scale s (Vec3.cross k v)))
    (Vec3.scale (Vec3.dot k v *. (1. -. c)) k)

let frame toctr =
  let up = if Float.abs (Float.abs toctr.Vec3.z -. 1.) < 0.1 then Vec3.unit_y else Vec3.unit_z in
  Vec3.normalize (Vec3.cross toctr up)

let shoot_unit ~(par_ : Image.par) (s : Scene.t) (ps : Photon.settings) ~spacing st mst k (light : Light.t) u =
  let ctr, rad = sphere u in
  let par = parallel light in
  let dir = axis light in
  let toctr0 = Vec3.sub ctr light.position in
  let dist = Vec3.length toctr0 in
  let spread = u.flags.target *. spacing in
  let spread = if par then spread else spread /. Float.max dist 1e-10 in
  let samples =
    match light.area with
    | Some a when light.photons.area_light && not par -> Some a
    | _ -> None
  in
  let spread = match samples with Some a -> spread *. Float.sqrt (float_of_int (a.n1 * a.n2)) | None -> spread in
  let dtheta = if par then spread else Float.atan spread in
  let maxtheta = if par then rad else if dist >= rad then Float.asin (rad /. dist) else Float.pi in
  let sh0 =
    { light; unit_ = u; spread; par; adc = (if ps.adc_bailout >= 0. then ps.adc_bailout else s.settings.adc_bailout);
      max_level = (if ps.max_trace_level > 0 then ps.max_trace_level else s.settings.max_trace_level);
      st; mst = st; hit_target = false; pig = Pigment.out (); rng = Random.State.make [| 0 |]; ps }
  in
  (* the interiors a photon starts in, found once per origin *)
  let inside o = List.map (fun (x : Object.t) -> x.interior) (Scene.containing s o) in
  let origins =
    match samples with
    | None -> [ (light.position, 1.) ]
    | Some a ->
        let off n i = if n <= 1 then 0. else (float_of_int i /. float_of_int (n - 1)) -. 0.5 in
        List.concat
          (List.init a.n1 (fun i ->
               List.init a.n2 (fun j ->
                   ( Vec3.add light.position (Vec3.add (Vec3.scale (off a.n1 i) a.axis1) (Vec3.scale (off a.n2 j) a.axis2)),
                     1. /. float_of_int (a.n1 * a.n2) ))))
  in
  let origins = List.map (fun (o, share) -> (o, share, if par then [] else inside o)) origins in
  let shoot_dir sh jt jp =
    List.iter
      (fun (org, share, media) ->
        let o, d =
          if par then begin
            let left = frame dir in
            let a = Vec3.dot dir (Vec3.normalize toctr0) in
            let base = Vec3.sub ctr (Vec3.scale (a *. dist) dir) in
            (Vec3.add base (rotate (Vec3.scale jt left) dir jp), dir)
          end
          else begin
            let t = Vec3.sub ctr org in
            let toctr = if Vec3.length t < 1e-10 then Vec3.unit_z else Vec3.normalize t in
            let left = frame toctr in
            let v = Vec3.add (Vec3.scale (-.Float.sin jt) left) (Vec3.scale (Float.cos jt) toctr) in
            (org, Vec3.normalize (rotate v toctr jp))
          end
        in
        let q = Vec3.m () in
        Vec3.load q (Vec3.add o d);
        let a = share *. Light.beam light q in
        if a >= 1e-5 then begin
          let media = if par then inside o else media in
          trace sh (Scene.image s) o d (Color.scale a light.color) 1. 0 0. true media
        end)
      origins
  in
  (* one ring of directions, with its own random numbers and store:
     rings are shot in batches on every domain, then taken in order *)
  let ring r =
    let rng = Random.State.make [| 1; k; r |] in
    let sh = { sh0 with st = Photon.store (); mst = Photon.store (); hit_target = false; pig = Pigment.out (); rng } in
    let th = float_of_int r *. dtheta in
    let dphi = if th < 1e-10 then 2. *. Float.pi else if par then dtheta /. th else dtheta /. Float.sin th in
    let minphi = -.Float.pi +. (dphi *. Random.State.float rng 1. *. 0.5) in
    let maxphi = Float.pi -. (dphi /. 2.) +. (minphi +. Float.pi) in
    let phi = ref minphi in
    while !phi < maxphi do
      let jp = !phi +. (dphi *. (Random.State.float rng 1. -. 0.5) *. ps.jitter) in
      let jt = th +. (dtheta *. (Random.State.float rng 1. -. 0.5) *. ps.jitter) in
      shoot_dir sh jt jp;
      phi := !phi +. dphi
    done;
    (sh.st, sh.mst, sh.hit_target)
  in
  if spread > 0. then begin
    let rings = int_of_float (Float.ceil (maxtheta /. dtheta)) in
    let batch = 64 in
    let start = ref 0 and hit_once = ref false and stop = ref false in
    while !start < rings && not !stop do
      let n = Int.min batch (rings - !start) in
      let got = Array.make n (st, mst, false) in
      par_ n (fun i -> got.(i) <- ring (!start + i));
      Array.iteri
        (fun i (rs, rms, hit) ->
          if not !stop then begin
            Photon.append st rs;
            Photon.append mst rms;
            (* POV-Ray's autostop: past that share of the cone, a ring
               that misses the target ends the shooting *)
            if hit then hit_once := true;
            let th = float_of_int (!start + i) *. dtheta in
            if !hit_once && (not hit) && th > ps.autostop *. maxtheta then stop := true
          end)
        got;
      start := !start + n
    done
  end

let shoot ?(par = Image.sequential) (s : Scene.t) (ps : Photon.settings) =
  let us = Array.fold_right units s.objects [] in
  let spacing = if ps.count > 0 then spacing_for_count s ps us else ps.spacing in
  let st = Photon.store () and mst = Photon.store () in
  let k = ref 0 in
  Array.iter
    (fun (light : Light.t) ->
      if not light.shadowless then
        List.iter
          (fun u ->
            incr k;
            if Photon.shoots u.flags ~light:light.photons then
              shoot_unit ~par_:par s ps ~spacing st mst !k light u)
          us)
    s.lights;
  (Photon.build ps st, if Photon.stored mst > 0 then Some (Photon.build ~volume:true ps mst) else None)

let prepare ?par (s : Scene.t) =
  match s.settings.photons with
  | Some ps when ps.state.map = None ->
      let m, mm = shoot ?par s ps in
      ps.state.map <- Some m;
      ps.state.media_map <- mm
  | _ -> ()
