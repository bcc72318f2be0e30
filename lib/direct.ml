(* Direct lighting in POV-Ray 3.7's classic model (see direct.mli). *)

(* a light this close to the surface's plane lights nothing *)
let light_min_cos = 1e-10

type opacity = { mutable alpha : float }

(* The shadows found at one point, light by light: light [j]'s is in
   [col.(3j) .. col.(3j + 2)] when [stamp.(j) = gen] (POV-Ray keeps the
   same per intersection, so that the layers of a texture and the
   textures of a texture map trace each shadow ray once) *)
type shadows = { mutable gen : int; mutable stamp : int array; mutable col : float array }

let shadows () = { gen = 1; stamp = [||]; col = [||] }
let forget c = c.gen <- c.gen + 1

(* POV-Ray's iridescence of channel [c] (0 red, 1 green, 2 blue): a thin
   film of the finish's thickness (varied by camlray's noise with
   [irid_turb]) seen at the cosines [cl] to the light and of the ray [d]
   to the normal [n] shifts the channel by its wavelength *)
let irid_k (s : Scene.t) (f : Finish.t) (p : Vec3.m) cl (d : Vec3.m) (n : Vec3.m) c =
  let t =
    if f.irid_turb = 0. then f.irid_thickness
    else f.irid_thickness *. (1. +. (((Noise.fractal3 5 p.mx p.my p.mz) -. 1.) *. f.irid_turb))
  in
  let ce = Float.abs ((n.mx *. d.mx) +. (n.my *. d.my) +. (n.mz *. d.mz)) in
  let phase = 2. *. Float.pi *. t *. (Float.abs cl +. ce) in
  let wl = s.settings.irid_wavelength in
  let w = if c = 0 then wl.r else if c = 1 then wl.g else wl.b in
  1. +. (f.irid *. Float.cos (phase /. w))

(* Diffuse and highlights of one light seen from [p], added into [out];
   the shadow is {!Shadow.light} (an area light's samples come here as
   point lights). Scalars throughout: nothing is allocated unless the
   shadow ray crosses something transparent. *)
let one_light s (f : Finish.t) (pc : Pigment.out) (k : opacity) (p : Vec3.m) (n : Vec3.m) (d : Vec3.m)
    (light : Light.t) (lp : Vec3.m) sampled (cache : shadows) j (out : Color.acc) =
  let alpha = k.alpha in
  let w = Shadow.walk () in
  let l = Shadow.toward w in
  (* [sampled]: a sample of an area light at [lp], as a point light *)
  if sampled then Light.direction_at light lp.mx lp.my lp.mz p l else Light.direction_into light p l;
  let nl = (n.mx *. l.lx) +. (n.my *. l.ly) +. (n.mz *. l.lz) in
  (* double_illuminate: a light behind lights as from the front, by |cos| *)
  let nl = if f.double_illuminate then Float.abs nl else nl in
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
    let sh = Shadow.passed w in
    (* a shadowless light is still tested for its projected_through *)
    let walk = match light.projected_through with Some _ -> true | None -> not light.shadowless in
    (* [j] < 0: an area light's sample, never kept *)
    if walk then
      if sampled then Shadow.point s w light p
      else if j >= 0 && cache.stamp.(j) = cache.gen then
        Color.acc_set sh cache.col.(3 * j) cache.col.((3 * j) + 1) cache.col.((3 * j) + 2)
      else begin
        Shadow.light s w light p;
        if j >= 0 then begin
          cache.stamp.(j) <- cache.gen;
          cache.col.(3 * j) <- sh.ar;
          cache.col.((3 * j) + 1) <- sh.ag;
          cache.col.((3 * j) + 2) <- sh.ab
        end
      end;
    let lr = if walk then lr *. sh.ar else lr
    and lg = if walk then lg *. sh.ag else lg
    and lb = if walk then lb *. sh.ab else lb in
    if not (lr = 0. && lg = 0. && lb = 0.) then
      if back then begin
        let k = alpha *. f.diffuse_back *. Float.pow (-.nl) f.brilliance in
        let ir = if f.irid > 0. then irid_k s f p nl d n 0 else 1. and ig = if f.irid > 0. then irid_k s f p nl d n 1 else 1.
        and ib = if f.irid > 0. then irid_k s f p nl d n 2 else 1. in
        out.ar <- out.ar +. (ir *. k *. (pc.r *. lr));
        out.ag <- out.ag +. (ig *. k *. (pc.g *. lg));
        out.ab <- out.ab +. (ib *. k *. (pc.b *. lb))
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
          cr := !cr *. irid_k s f p nl d n 0;
          cg := !cg *. irid_k s f p nl d n 1;
          cb := !cb *. irid_k s f p nl d n 2
        end;
        out.ar <- out.ar +. !cr;
        out.ag <- out.ag +. !cg;
        out.ab <- out.ab +. !cb
      end
  end

let no_cache = shadows ()

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
  mutable ik : opacity;
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
        ik = { alpha = 1. }; ip = Vec3.m (); inn = Vec3.m (); id = Vec3.m (); ipos = Vec3.m (); isum = Color.acc 0. })

(* sample (i, j) of the area light in [il] shading as a point light there *)
let illum_sample (il : illum) i j (o : Color.acc) =
  let light = il.ilight and a = il.iarea in
  Light.position_into light a il.ip (Light.offset a.n1 i) (Light.offset a.n2 j) il.ipos;
  Color.acc_set o 0. 0. 0.;
  match il.iscene with
  | Some s -> one_light s il.ifinish il.ipc il.ik il.ip il.inn il.id light il.ipos true no_cache (-1) o
  | None -> ()

(* [one_light]'s position when the light is where it stands (unread) *)
let own_position = Vec3.m ()

let lights (s : Scene.t) cache (ls : Light.t array) (f : Finish.t) (pc : Pigment.out) (k : opacity) p n d
    (out : Color.acc) =
  let nl = Array.length ls in
  if Array.length cache.stamp < nl then begin
    cache.stamp <- Array.make nl 0;
    cache.col <- Array.make (3 * nl) 0.
  end;
  for j = 0 to nl - 1 do
    let light = Array.unsafe_get ls j in
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
    | _ -> one_light s f pc k p n d light own_position false cache j out
  done
