open Color

(* if-based min/max: Float.min/max order NaN and -0 through a C call *)
let[@inline] fmax (a : float) b = if a >= b then a else b
let[@inline] fmin (a : float) b = if a <= b then a else b
let[@inline] maxc (c : Color.t) = fmax c.r (fmax c.g c.b)

type t = { scene : Scene.t; emitters : Emitter.t array; nee : bool; has_env : bool }

let prepare ?(nee = true) ?(extra = []) (scene : Scene.t) =
  { scene; emitters = Array.append (Emitter.of_scene scene) (Array.of_list extra); nee;
    has_env = not (Sky.is_empty scene.sky && is_black scene.background) }

(* The environment light: the sky_sphere, or the uniform background. *)
let env (s : Scene.t) dir =
  if Sky.is_empty s.sky then s.background else Sky.eval s.sky ~background:s.background dir

let[@inline] power a b =
  let a2 = a *. a and b2 = b *. b in
  if a2 +. b2 = 0. then 0. else a2 /. (a2 +. b2)

(* Light that passes straight through along a shadow ray: surfaces that
   neither refract (ior 1) nor are opaque let (f P + t) through, as a glass
   lobe with eta 1 would; anything else blocks (light bent by refraction
   is found by the paths, not by shadow rays). [blocks o]: every crossing
   of [o] blocks (one is enough to find). *)
let blocks (o : Object.t) =
  o.interior.ior <> 1.
  || match o.texture with [] -> true | (layer : Texture.layer) :: _ -> Pigment.opaque layer.pigment

let transmittance (s : Scene.t) p wi dist =
  let ray = Ray.make p wi in
  let acc = ref white in
  let open_ =
    Scene.occluders s ray Ray.shadow_epsilon dist blocks (fun (o : Object.t) t ->
        match o.texture with
        | [] -> false
        | (layer : Texture.layer) :: _ ->
            let c = Pigment.eval layer.pigment (Ray.at ray t) in
            if c.filter +. c.transmit <= 0. || o.interior.ior <> 1. then false
            else begin
              acc := mul !acc (add (scale c.filter c.c) (gray c.transmit));
              not (is_black !acc)
            end)
  in
  if open_ then !acc else black

(* The random dimensions of one sample: 0-1 pixel, 2-3 lens, then a block
   per bounce. *)
let dims_per_bounce t = 8 + (2 * Array.length t.emitters)
let d_lobe = 0 and d_dir = 1 and d_rr = 3 and d_env = 4 and d_light = 6

(* Next-event estimation at a vertex: every emitter, plus the environment. *)
let direct t sampler base (m : Material.t) p n wo =
  let s = t.scene in
  let acc = ref black in
  for i = 0 to Array.length t.emitters - 1 do
    let e = Array.unsafe_get t.emitters i in
    let u = Sampler.get sampler (base + d_light + (2 * i))
    and v = Sampler.get sampler (base + d_light + (2 * i) + 1) in
    match Emitter.sample e p u v with
    | None -> ()
    | Some ls ->
        let ci = Vec3.dot n ls.wi in
        if ci > 0. then begin
          let f = Bsdf.eval m ~n ~wo ~wi:ls.wi in
          if not (is_black f) then
            match e with
            | Delta l | Area { light = l; _ } ->
                let tr = if l.shadowless then white else transmittance s p ls.wi ls.dist in
                acc := add !acc (scale ci (mul f (mul tr ls.value)))
            | Sphere { obj; _ } -> (
                match Scene.intersect s (Ray.make p ls.wi) Ray.epsilon infinity with
                | Some h when h.obj == obj ->
                    let le = Emitter.emission obj h.point in
                    let pb = Bsdf.pdf m ~n ~wo ~wi:ls.wi in
                    let w = power ls.pdf pb in
                    acc := add !acc (scale (ci *. w /. ls.pdf) (mul f le))
                | _ -> ())
        end
  done;
  (* the environment is sampled cosine-weighted about the normal *)
  if t.has_env then begin
    let wi =
      Bsdf.cosine_hemisphere n (Sampler.get sampler (base + d_env))
        (Sampler.get sampler (base + d_env + 1))
    in
    let ci = Vec3.dot n wi in
    if ci > 0. then begin
      let f = Bsdf.eval m ~n ~wo ~wi in
      if not (is_black f) then begin
        let pl = ci /. Float.pi and pb = Bsdf.pdf m ~n ~wo ~wi in
        let tr = transmittance s p wi infinity in
        if not (is_black tr) then
          acc := add !acc (scale (ci *. power pl pb /. pl) (mul f (mul tr (env s wi))))
      end
    end
  end;
  !acc

(* What the previous vertex needs to weight light found by its bounce. *)
type prev = Camera | Specular | Smooth of { p : Vec3.t; n : Vec3.t; pdf : float }

let li t sampler ~max_depth (ray : Ray.t) =
  let s = t.scene in
  let per = dims_per_bounce t in
  let rec go (ray : Ray.t) depth thr acc prev =
    let tmin = if depth = 0 then 0. else Ray.epsilon in
    match Scene.intersect s ray tmin infinity with
    | None ->
        let w =
          match prev with
          | Smooth { n; pdf; _ } when t.nee ->
              power pdf (fmax 0. (Vec3.dot n ray.dir) /. Float.pi)
          | _ -> 1.
        in
        if t.has_env then madd acc w (mul thr (env s ray.dir)) else acc
    | Some hit ->
        let obj = hit.obj in
        let wo = Vec3.neg ray.dir in
        let entering = Vec3.dot hit.normal ray.dir < 0. in
        let n = if entering then hit.normal else Vec3.neg hit.normal in
        (* a ray leaving a solid travelled inside it: interior fade *)
        let thr = if entering then thr else mul thr (Interior.fade obj.interior hit.t) in
        let m =
          Material.of_texture obj.texture obj.interior hit.point ~cos_o:(Vec3.dot n wo) ~entering
        in
        let acc =
          if is_black m.emission then acc
          else
            let w =
              match (prev, Emitter.find t.emitters obj) with
              | Smooth { p; pdf; _ }, Some e when t.nee ->
                  power pdf (Emitter.pdf e p hit.point hit.normal)
              | _ -> 1.
            in
            add acc (scale w (mul thr m.emission))
        in
        if depth >= max_depth then acc
        else
          let base = 4 + (depth * per) in
          let acc =
            if t.nee && Bsdf.has_smooth m then
              add acc (mul thr (direct t sampler base m hit.point n wo))
            else acc
          in
          match
            Bsdf.sample m ~n ~wo
              (Sampler.get sampler (base + d_lobe))
              (Sampler.get sampler (base + d_dir))
              (Sampler.get sampler (base + d_dir + 1))
          with
          | None -> acc
          | Some bs ->
              let thr = mul thr bs.weight in
              let q = if depth >= 3 then fmin 0.95 (maxc thr) else 1. in
              if q <= 0. || Sampler.get sampler (base + d_rr) >= q then acc
              else
                let prev =
                  if bs.delta then Specular else Smooth { p = hit.point; n; pdf = bs.pdf }
                in
                go (Ray.make hit.point bs.wi) (depth + 1) (scale (1. /. q) thr) acc prev
  in
  go ray 0 white black Camera

let pixel t ~width ~height ~seed ~spp ~max_depth x y =
  let side = int_of_float (Float.sqrt (float_of_int spp)) in
  let strat = side * side = spp in
  let acc = ref black in
  for k = 0 to spp - 1 do
    let sampler = Sampler.create ~seed ~pixel:((y * width) + x) ~sample:k in
    let u1 = Sampler.get sampler 0 and u2 = Sampler.get sampler 1 in
    let jx, jy =
      if strat then
        ( (float_of_int (k mod side) +. u1) /. float_of_int side,
          (float_of_int (k / side) +. u2) /. float_of_int side )
      else (u1, u2)
    in
    let sx, sy =
      Camera.pixel_coords ~width ~height (float_of_int x +. jx) (float_of_int y +. jy)
    in
    let ray =
      Camera.ray_lens t.scene.camera sx sy (Sampler.get sampler 2) (Sampler.get sampler 3)
    in
    let c = li t sampler ~max_depth ray in
    (* a non-finite sample (never expected) would poison the pixel: drop it *)
    if Float.is_finite (c.r +. c.g +. c.b) then acc := add !acc c
  done;
  scale (1. /. float_of_int spp) !acc
