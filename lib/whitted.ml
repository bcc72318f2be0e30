open Color

let light_min_cos = 1e-10

(* Light reaching [p] from a light along [l] over [dist]: the product of
   (f*P + t) of every surface crossed; black when an opaque one blocks. *)
let shadow_filter (s : Scene.t) p l dist =
  let ray = Ray.make p l in
  let acc = ref white in
  let visible =
    Scene.occluders s ray Ray.shadow_epsilon dist (fun (o : Object.t) t ->
        let q = Ray.at ray t in
        List.iter
          (fun (layer : Texture.layer) ->
            let c = Pigment.eval layer.pigment q in
            acc := mul !acc (add (scale c.filter c.c) (gray c.transmit)))
          o.texture;
        not (is_black !acc))
  in
  if visible then !acc else black

(* POV-Ray's approximate metallic Fresnel term, x = angle / 90 degrees. *)
let metallic_tint m cos_angle (pc : Color.t) =
  if m = 0. then white
  else
    let x = Float.acos (Float.min 1. (Float.abs cos_angle)) /. (Float.pi /. 2.) in
    let f = (0.014567225 /. ((x -. 1.12) ** 2.)) -. 0.011612903 in
    let f = Float.min 1. (Float.max 0. f) in
    let k = m *. (1. -. f) in
    make (1. +. (k *. (pc.r -. 1.))) (1. +. (k *. (pc.g -. 1.))) (1. +. (k *. (pc.b -. 1.)))

let fresnel n c =
  let g2 = (n *. n) +. (c *. c) -. 1. in
  if g2 <= 0. then 1.
  else
    let g = Float.sqrt g2 in
    let a = (g -. c) /. (g +. c) and b = ((c *. (g +. c)) -. 1.) /. ((c *. (g -. c)) +. 1.) in
    0.5 *. a *. a *. (1. +. (b *. b))

let direct (s : Scene.t) (f : Finish.t) (pc : Color.t) alpha p n d =
  let acc = ref black in
  Array.iter
    (fun (light : Light.t) ->
      let l, dist = Light.direction_to light p in
      let nl = Vec3.dot n l in
      if nl >= light_min_cos then begin
        let att = Light.attenuation light p in
        if att > 0. then begin
          let lc = scale att light.color in
          let lc = if light.shadowless then lc else mul lc (shadow_filter s p l dist) in
          if not (is_black lc) then begin
            if f.diffuse > 0. then
              acc := madd !acc (alpha *. f.diffuse *. Float.pow nl f.brilliance) (mul pc lc);
            if not light.shadowless then begin
              let lm = mul lc (metallic_tint f.metallic nl pc) in
              if f.phong > 0. then begin
                let r = Vec3.madd d (-2. *. Vec3.dot d n) n in
                let rl = Vec3.dot r l in
                if rl > 0. then acc := madd !acc (f.phong *. Float.pow rl f.phong_size) lm
              end;
              if f.specular > 0. then begin
                let h = Vec3.normalize (Vec3.sub l d) in
                let nh = Vec3.dot n h in
                if nh > 0. then
                  acc := madd !acc (f.specular *. Float.pow nh (1. /. f.roughness)) lm
              end
            end
          end
        end
      end)
    s.lights;
  !acc

(* [medium]: the interior the ray travels through (None: outside). *)
let rec trace_ray (s : Scene.t) (ray : Ray.t) level weight medium =
  if level > s.settings.max_trace_level || weight < s.settings.adc_bailout then black
  else
    let tmin = if level = 1 then 0. else Ray.epsilon in
    match Scene.intersect s ray tmin infinity with
    | None -> s.background
    | Some hit ->
        let c = shade s ray hit level weight medium in
        (match medium with
        | Some (i : Interior.t) -> mul c (Interior.fade i hit.t)
        | None -> c)

and shade s ray hit level weight medium =
  let d = ray.dir in
  let outward = hit.normal in
  let entering = Vec3.dot outward d < 0. in
  let n = if entering then outward else Vec3.neg outward in
  let p = hit.point in
  (* TODO(layers): only the top layer is shaded for now *)
  let layer = List.hd hit.obj.texture in
  let f = layer.finish in
  let pig = Pigment.eval layer.pigment p in
  let pc = pig.c in
  let alpha =
    if s.settings.legacy_alpha then 1. -. ((pig.filter *. Color.max_channel pc) +. pig.transmit)
    else 1. -. pig.filter -. pig.transmit
  in
  let local =
    madd (direct s f pc alpha p n d) alpha
      (mul pc (add (mul f.ambient s.settings.ambient_light) f.emission))
  in
  let cos_i = -.Vec3.dot d n in
  (* relative index of refraction across this surface *)
  let ior = hit.obj.interior.ior in
  let eta = if entering then 1. /. ior else ior in
  let rf = f.reflection in
  let kr =
    if not (Finish.has_reflection f) then black
    else
      let k =
        if rf.fresnel then if ior = 1. then 0. else fresnel (1. /. eta) cos_i
        else Float.pow (1. -. cos_i) rf.falloff
      in
      let k = Color.add rf.rmin (Color.scale k (Color.add rf.rmax (Color.scale (-1.) rf.rmin))) in
      Color.mul k (metallic_tint rf.rmetallic cos_i pc)
  in
  let reflect () = Vec3.madd d (2. *. cos_i) n in
  let c =
    if Color.is_black kr then local
    else
      let w = weight *. Color.max_channel kr in
      let rc = trace_ray s (Ray.make p (reflect ())) (level + 1) w medium in
      let rc = if rf.exponent = 1. then rc else Color.pow rc (1. /. rf.exponent) in
      Color.add local (Color.mul kr rc)
  in
  let tr = add (scale pig.filter pc) (gray pig.transmit) in
  if Color.luminance tr <= s.settings.adc_bailout then c
  else
    let next_medium = if entering then Some hit.obj.interior else None in
    let w = weight *. Color.max_channel tr in
    if eta = 1. then
      (* same index on both sides: straight through, no trace level used *)
      Color.add c (Color.mul tr (trace_ray s (Ray.make p d) level w next_medium))
    else
      let k = 1. +. (eta *. eta *. ((cos_i *. cos_i) -. 1.)) in
      if k < 0. then
        (* total internal reflection: unfiltered *)
        Color.add c (trace_ray s (Ray.make p (reflect ())) (level + 1) weight medium)
      else
        let t = Vec3.madd (Vec3.scale eta d) ((eta *. cos_i) -. Float.sqrt k) n in
        Color.add c (Color.mul tr (trace_ray s (Ray.make p t) (level + 1) w next_medium))

let trace s ray = trace_ray s ray 1 1. None

let pixel (s : Scene.t) ~width ~height x y =
  let sx, sy =
    Camera.pixel_coords ~width ~height (float_of_int x +. 0.5) (float_of_int y +. 0.5)
  in
  trace s (Camera.ray s.camera sx sy)
