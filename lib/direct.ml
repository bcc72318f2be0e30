(* Direct lighting in POV-Ray 3.7's classic model (see direct.mli). *)

(* a light this close to the surface's plane lights nothing *)
let light_min_cos = 1e-10

type opacity = { mutable alpha : float }

(* POV-Ray's film thickness at [p] (trace.cpp's ComputeIridColour): the
   finish's thickness, times 1 + (2 T - 1) turbulence with T POV-Ray's
   Turbulence of the point with 5 octaves, omega 0.5 and lambda 2 in the
   scene's noise generator (written out here, as {!Noise.turbulence}
   computes it: the first octave clamped to [0, 1] for generators 2 and
   3, each octave of theirs 2 noise - 0.5); the thickness and the
   turbulence in single precision, as POV-Ray keeps them. Inlined: the
   float it returns is not boxed (a call of Noise.turbulence here boxed
   4.9 words a camera ray on irid.pov, measured). *)
let single = Floats.single

let[@inline] irid_thickness (f : Finish.t) (p : Vec3.m) =
  let th = single f.irid_thickness in
  if f.irid_turb = 0. then th
  else begin
    let gen = !Pattern.scene_noise_generator in
    let x = p.mx and y = p.my and z = p.mz in
    let t = ref 0. and l = ref 1. and o = ref 0.5 in
    for i = 1 to 5 do
      let li = !l in
      let nz = Noise.noise gen (x *. li) (y *. li) (z *. li) in
      let v = if gen <= 1 then nz else (2.0 *. nz) -. 0.5 in
      if i = 1 then t := (if gen <= 1 then v else if v < 0. then 0. else if 1. < v then 1. else v)
      else begin
        t := !t +. (!o *. v);
        o := !o *. 0.5
      end;
      l := li *. 2.
    done;
    th *. (1.0 +. (((2.0 *. !t) -. 1.0) *. single f.irid_turb))
  end

(* What one light, or one sample of an area light that shades per
   sample, brings to the point: its colour there (attenuated and
   shadowed), the cosine [nl] of its direction to the normal (as the
   finish takes it: |cos| with double_illuminate), and the cosine
   iridescence is found with. All floats, stored flat: passing it boxes
   nothing. *)
type lightlet = {
  mutable lr : float;
  mutable lg : float;
  mutable lb : float;
  mutable nl : float;
  mutable icos : float;
  (* iridescence's factors of the three channels, set by [irid_into] *)
  mutable ir : float;
  mutable ig : float;
  mutable ib : float;
  mutable hl : float;
      (** 1: highlights drawn; 0: not (radiosity's gather rays); a float,
          so that the record stays one of floats, stored flat *)
}

(* The lightlet handed to [shade], a sample's position and the area
   light's axes seen from the lit point *)
type scratch = { ll : lightlet; q : Vec3.m; ax : Light.axes }

(* The shadows found at one point, light by light: light [j]'s is in
   [col.(3j) .. col.(3j + 2)] when [stamp.(j) = gen] (POV-Ray keeps the
   same per intersection, so that the layers of a texture and the
   textures of a texture map trace each shadow ray once); with them the
   shadow walk of the domain that made the record and a scratch of its
   own, reached from here rather than looked up per light (a lookup is a
   call, and every float live across it is spilled) *)
type shadows = {
  mutable gen : int;
  mutable stamp : int array;
  mutable col : float array;
  mutable highlights : bool;
  w : Shadow.walk;
  sc : scratch;
}

let shadows () =
  { gen = 1; stamp = [||]; col = [||]; highlights = true; w = Shadow.walk ();
    sc = { ll = { lr = 0.; lg = 0.; lb = 0.; nl = 0.; icos = 0.; ir = 1.; ig = 1.; ib = 1.; hl = 1. }; q = Vec3.m ();
           ax = Light.axes () } }

let walk c = c.w

let set_highlights c h = c.highlights <- h
let forget c = c.gen <- c.gen + 1

(* POV-Ray's iridescence: a thin film of {!irid_thickness} seen at the
   cosines [c.icos] to the light and of the ray [d] to the normal [n]
   shifts each channel by its wavelength (the amount and the wavelengths
   in single precision, as POV-Ray keeps them), the factors into [c.ir],
   [c.ig], [c.ib]. Not inlined: [shade] held six copies of it (with
   -inline 200), 23.6 KB of code between the lines every light runs. *)
let[@inline never] irid_into (s : Scene.t) (f : Finish.t) (p : Vec3.m) (d : Vec3.m) (n : Vec3.m) (c : lightlet) =
  let t = irid_thickness f p in
  let ce = Float.abs ((n.mx *. d.mx) +. (n.my *. d.my) +. (n.mz *. d.mz)) in
  let phase = 2. *. Float.pi *. t *. (Float.abs c.icos +. ce) in
  let wl = s.settings.irid_wavelength in
  let k = single f.irid in
  c.ir <- 1. +. (k *. Float.cos (phase /. single wl.r));
  c.ig <- 1. +. (k *. Float.cos (phase /. single wl.g));
  c.ib <- 1. +. (k *. Float.cos (phase /. single wl.b))

(* Diffuse and highlights of the lightlet [c] coming along [l] (the unit
   direction toward it), on the back side with [back], added into [out] *)
let shade s (f : Finish.t) (pc : Pigment.out) (k : opacity) (p : Vec3.m) (n : Vec3.m) (d : Vec3.m)
    (light : Light.t) (l : Light.dir) back (c : lightlet) (out : Color.acc) =
  let alpha = k.alpha and lr = c.lr and lg = c.lg and lb = c.lb and nl = c.nl in
  if back then begin
    let k = alpha *. f.diffuse_back *. Float.pow (-.nl) f.brilliance in
    if f.irid > 0. then irid_into s f p d n c
    else begin
      c.ir <- 1.;
      c.ig <- 1.;
      c.ib <- 1.
    end;
    out.ar <- out.ar +. (c.ir *. k *. (pc.r *. lr));
    out.ag <- out.ag +. (c.ig *. k *. (pc.g *. lg));
    out.ab <- out.ab +. (c.ib *. k *. (pc.b *. lb))
  end
  else begin
    let cr = ref 0. and cg = ref 0. and cb = ref 0. in
    if f.diffuse > 0. then begin
      let k = alpha *. f.diffuse *. (if f.brilliance = 1. then nl else Float.pow nl f.brilliance) in
      cr := !cr +. (k *. (pc.r *. lr));
      cg := !cg +. (k *. (pc.g *. lg));
      cb := !cb +. (k *. (pc.b *. lb))
    end;
    if c.hl > 0. && not light.shadowless then begin
      let m = f.metallic in
      let mk = if m = 0. then 0. else Finish.metallic_k m nl in
      let mr = lr *. Finish.tint m mk pc.r and mg = lg *. Finish.tint m mk pc.g and mb = lb *. Finish.tint m mk pc.b in
      if f.phong > 0. then begin
        (* r = d - 2 (d.n) n, the mirror direction *)
        let k = -2. *. Vec3.dot_m d n in
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
    if f.irid > 0. then begin
      (* POV-Ray's iridescence scales this light's diffuse and highlights *)
      irid_into s f p d n c;
      cr := !cr *. c.ir;
      cg := !cg *. c.ig;
      cb := !cb *. c.ib
    end;
    out.ar <- out.ar +. !cr;
    out.ag <- out.ag +. !cg;
    out.ab <- out.ab +. !cb
  end

(* The shadow of light [j] at [p] (its direction in [toward w]) into
   [passed w]: kept in [cache], or traced and kept *)
let find_shadow s w (light : Light.t) p cache j =
  let sh = Shadow.passed w in
  if cache.stamp.(j) = cache.gen then
    Color.acc_set sh cache.col.(3 * j) cache.col.((3 * j) + 1) cache.col.((3 * j) + 2)
  else begin
    Shadow.light s w light p;
    cache.stamp.(j) <- cache.gen;
    cache.col.(3 * j) <- sh.ar;
    cache.col.((3 * j) + 1) <- sh.ag;
    cache.col.((3 * j) + 2) <- sh.ab
  end

(* Diffuse and highlights of one light seen from [p], added into [out];
   the shadow is {!Shadow.light} (an area light's samples averaged).
   Scalars throughout: nothing is allocated unless the shadow ray crosses
   something transparent. *)
let one_light s (f : Finish.t) (pc : Pigment.out) (k : opacity) (p : Vec3.m) (n : Vec3.m) (d : Vec3.m)
    (light : Light.t) (cache : shadows) j (out : Color.acc) =
  let w = cache.w and c = cache.sc.ll in
  let l = Shadow.toward w in
  Light.direction_into light p l;
  let nl = (n.mx *. l.lx) +. (n.my *. l.ly) +. (n.mz *. l.lz) in
  (* double_illuminate: a light behind lights as from the front, by |cos| *)
  let nl = if f.double_illuminate then Float.abs nl else nl in
  let front = nl >= light_min_cos in
  let back = (not front) && f.diffuse_back > 0. && -.nl >= light_min_cos in
  let att = if not (front || back) then 0. else Light.attenuation_m light p in
  if att > 0. then begin
    let lr = att *. light.color.r and lg = att *. light.color.g and lb = att *. light.color.b in
    (* no tuple: the channels stay unboxed *)
    let sh = Shadow.passed w in
    (* a shadowless light is still tested for its projected_through *)
    let walk = match light.projected_through with Some _ -> true | None -> not light.shadowless in
    if walk then find_shadow s w light p cache j;
    let lr = if walk then lr *. sh.ar else lr
    and lg = if walk then lg *. sh.ag else lg
    and lb = if walk then lb *. sh.ab else lb in
    if not (lr = 0. && lg = 0. && lb = 0.) then begin
      c.lr <- lr;
      c.lg <- lg;
      c.lb <- lb;
      c.nl <- nl;
      c.icos <- nl;
      shade s f pc k p n d light l back c out
    end
  end

(* An area light with area_illumination, as POV-Ray 3.7 has it (trace.cpp,
   ComputeOneDiffuseLight and ComputeFullAreaDiffuseLight): its shadow is
   found as without it (the samples' shadows averaged adaptively) for the
   light's colour unattenuated, and the centre facing away skips nothing;
   when some light passes, every sample of the grid (all of them, adaptive
   or not) shades as a point light at its position with 1/(n1 n2) of that
   shadowed colour, attenuated (fade, spotlight) along its own ray and
   skipped when it faces away; iridescence by the centre's direction. *)
let area_light s (f : Finish.t) (pc : Pigment.out) (k : opacity) (p : Vec3.m) (n : Vec3.m) (d : Vec3.m)
    (light : Light.t) (a : Light.area) (cache : shadows) j (out : Color.acc) =
  let w = cache.w and sc = cache.sc in
  let l = Shadow.toward w in
  Light.direction_into light p l;
  let nl0 = (n.mx *. l.lx) +. (n.my *. l.ly) +. (n.mz *. l.lz) in
  let nl0 = if f.double_illuminate then Float.abs nl0 else nl0 in
  let sh = Shadow.passed w in
  let walk = match light.projected_through with Some _ -> true | None -> not light.shadowless in
  if walk then find_shadow s w light p cache j;
  let lr = if walk then light.color.r *. sh.ar else light.color.r
  and lg = if walk then light.color.g *. sh.ag else light.color.g
  and lb = if walk then light.color.b *. sh.ab else light.color.b in
  if not (lr = 0. && lg = 0. && lb = 0.) then begin
    let nn = float_of_int (a.n1 * a.n2) in
    let lr = lr /. nn and lg = lg /. nn and lb = lb /. nn in
    let c = sc.ll and q = sc.q and ax = sc.ax in
    Light.axes_into light a p ax;
    for v = 0 to a.n2 - 1 do
      for u = 0 to a.n1 - 1 do
        Light.sample_on light a ax u v q;
        Light.direction_at light q.mx q.my q.mz p l;
        let nl = (n.mx *. l.lx) +. (n.my *. l.ly) +. (n.mz *. l.lz) in
        let nl = if f.double_illuminate then Float.abs nl else nl in
        let front = nl >= light_min_cos in
        let back = (not front) && f.diffuse_back > 0. && -.nl >= light_min_cos in
        if front || back then begin
          let att = Light.attenuation_shifted light q.mx q.my q.mz p in
          if att > 0. then begin
            c.lr <- lr *. att;
            c.lg <- lg *. att;
            c.lb <- lb *. att;
            c.nl <- nl;
            c.icos <- nl0;
            shade s f pc k p n d light l back c out
          end
        end
      done
    done
  end

let lights (s : Scene.t) cache (ls : Light.t array) (f : Finish.t) (pc : Pigment.out) (k : opacity) p n d
    (out : Color.acc) =
  let nl = Array.length ls in
  if Array.length cache.stamp < nl then begin
    cache.stamp <- Array.make nl 0;
    cache.col <- Array.make (3 * nl) 0.
  end;
  let sc = cache.sc in
  sc.ll.hl <- (if cache.highlights then 1. else 0.);
  for j = 0 to nl - 1 do
    let light = Array.unsafe_get ls j in
    match light.area with
    | Some a when a.area_illumination -> area_light s f pc k p n d light a cache j out
    | _ -> one_light s f pc k p n d light cache j out
  done

(* Photons: each gathered photon lights the point as a light from the
   way it came (POV-Ray's ComputePhotonDiffuseLight) *)
type photons_scratch = { pl : lightlet; pd : Light.dir; sum : Color.acc }

let photons_key =
  Scratch.key (fun () ->
      { pl = { lr = 0.; lg = 0.; lb = 0.; nl = 0.; icos = 0.; ir = 1.; ig = 1.; ib = 1.; hl = 1. }; pd = Light.dir ();
        sum = Color.acc 0. })

(* highlights drawn: a light that casts shadows *)
let photon_source = Light.point Vec3.zero Color.black

let photons s (m : Photon.map) cache (f : Finish.t) (pc : Pigment.out) (k : opacity) (p : Vec3.m) (n : Vec3.m)
    (n0 : Vec3.m) (d : Vec3.m) (out : Color.acc) =
  let q = Photon.query () in
  Photon.gather m q p n;
  let cnt = Photon.found q in
  if cnt > 0 then begin
    let sc = Scratch.get photons_key in
    let c = sc.pl and l = sc.pd and sum = sc.sum in
    c.hl <- (if cache.highlights then 1. else 0.);
    Color.acc_set sum 0. 0. 0.;
    for j = 0 to cnt - 1 do
      let i = Photon.index q j in
      l.lx <- Photon.direction m i 0;
      l.ly <- Photon.direction m i 1;
      l.lz <- Photon.direction m i 2;
      (* POV-Ray's compensation for the photons' slant: the flux over
         the cosine to the unperturbed normal, at most tenfold *)
      let a = (n0.mx *. l.lx) +. (n0.my *. l.ly) +. (n0.mz *. l.lz) in
      let a = Floats.fmax 0.1 (Floats.fmin 1. a) in
      let nl = (n.mx *. l.lx) +. (n.my *. l.ly) +. (n.mz *. l.lz) in
      let nl = if f.double_illuminate then Float.abs nl else nl in
      let back = nl < 1e-10 in
      if (not back) || f.diffuse_back <> 0. then begin
        c.lr <- Photon.flux m i 0 /. a;
        c.lg <- Photon.flux m i 1 /. a;
        c.lb <- Photon.flux m i 2 /. a;
        c.nl <- nl;
        c.icos <- nl;
        shade s f pc k p n d photon_source l back c sum
      end
    done;
    let ar = Photon.area q in
    Color.acc_set out (out.ar +. (sum.ar /. ar)) (out.ag +. (sum.ag /. ar)) (out.ab +. (sum.ab /. ar))
  end
