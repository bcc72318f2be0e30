open Color

let light_min_cos = 1e-10

(* (f*P + t) of a texture at a point: what a surface lets through. *)
let rec texture_filter (tex : Texture.t) q =
  List.fold_left
    (fun acc (layer : Texture.layer) ->
      match layer.tmap with
      | Some m ->
          let f =
            List.fold_left (fun f (k, t) -> madd f k (texture_filter t q)) black (Texture.blend m q)
          in
          mul acc f
      | None ->
          let c = Pigment.eval layer.pigment q in
          mul acc (add (scale c.filter c.c) (gray c.transmit)))
    white tex

(* shadow rays fade only with a fade_power (povray 3.7: fade_power 0 fades
   what the eye sees through, by 1/2, but not the light) *)
let has_fade (i : Interior.t) = i.fade_distance <> 0. && i.fade_power <> 0.

(* The walk's state lives in a per-domain record, so that the callback is
   a closed function (no closure and refs per shadow ray); texture_filter
   traces nothing, so walks never nest on a domain. *)
type shadow_walk = { mutable acc : Color.t; mutable faders : (Object.t * float) list; mutable ray : Ray.t }

let shadow_key =
  Domain.DLS.new_key (fun () -> { acc = white; faders = []; ray = Ray.make Vec3.zero Vec3.unit_z })

let shadow_hit (o : Object.t) t =
  let w = Domain.DLS.get shadow_key in
  w.acc <- mul w.acc (texture_filter o.texture (Ray.at w.ray t));
  if has_fade o.interior then w.faders <- (o, t) :: w.faders;
  not (is_black w.acc)

(* Light reaching [p] from [dist] along the unit direction [l]: the product
   of (f*P + t) of every surface crossed, with interior fade over the
   lengths travelled inside fading objects; black when something opaque
   blocks. *)
let shadow_filter (s : Scene.t) p l dist =
  let ray = Ray.make p l in
  let w = Domain.DLS.get shadow_key in
  w.acc <- white;
  w.faders <- [];
  w.ray <- ray;
  let visible = Scene.occluders s ray Ray.shadow_epsilon dist shadow_hit in
  let acc = ref w.acc and faders = w.faders in
  w.faders <- [];
  if not visible then black
  else if faders = [] then !acc
  else begin
    (* group crossings by object; inside segments between them get faded *)
    let seen = ref [] in
    List.iter
      (fun ((o : Object.t), _) ->
        if not (List.memq o !seen) then begin
          seen := o :: !seen;
          let ts = List.filter_map (fun (o', t) -> if o' == o then Some t else None) faders in
          let ts = List.sort Float.compare ts in
          let bounds = (0. :: ts) @ [ dist ] in
          let rec segs = function
            | a :: (b :: _ as rest) ->
                if b > a && Object.inside o (Ray.at ray (0.5 *. (a +. b))) then
                  acc := mul !acc (Interior.fade o.interior (b -. a));
                segs rest
            | _ -> ()
          in
          segs bounds
        end)
      faders;
    !acc
  end

(* Shadow colour of one light at [p]: area lights average their samples. *)
let light_shadow s (light : Light.t) p l dist =
  match light.area with
  | None -> shadow_filter s p l dist
  | Some a ->
      Light.average_area a (fun i j ->
          let q = Light.sample_position light a p i j in
          let v = Vec3.sub q p in
          let d = Vec3.length v in
          shadow_filter s p (Vec3.scale (1. /. d) v) d)

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

(* Diffuse and highlights of every light for one texture layer. *)
(* Diffuse and highlights of one light seen from [p]; the shadow is
   [light_shadow] (an area light's samples come here as point lights). *)
let one_light s (f : Finish.t) (pc : Color.t) alpha p n d (light : Light.t) =
  let l, dist = Light.direction_to light p in
  let nl = Vec3.dot n l in
  let front = nl >= light_min_cos in
  let back = (not front) && f.diffuse_back > 0. && -.nl >= light_min_cos in
  let att = if front || back then Light.attenuation light p else 0. in
  if att <= 0. then black
  else
    let lc = scale att light.color in
    let lc = if light.shadowless then lc else mul lc (light_shadow s light p l dist) in
    if is_black lc then black
    else if back then scale (alpha *. f.diffuse_back *. Float.pow (-.nl) f.brilliance) (mul pc lc)
    else begin
      let acc = ref black in
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
          if nh > 0. then acc := madd !acc (f.specular *. Float.pow nh (1. /. f.roughness)) lm
        end
      end;
      !acc
    end

(* Diffuse and highlights of every light for one texture layer. *)
let direct (s : Scene.t) (f : Finish.t) (pc : Color.t) alpha p n d =
  let acc = ref black in
  for k = 0 to Array.length s.lights - 1 do
    let light = Array.unsafe_get s.lights k in
    let c =
      match light.area with
      | Some a when a.area_illumination ->
          (* every sample shades as a point light; averaged like shadows *)
          Light.average_area a (fun i j ->
              let q = Light.sample_position light a p i j in
              one_light s f pc alpha p n d { light with position = q; area = None })
      | _ -> one_light s f pc alpha p n d light
    in
    acc := add !acc c
  done;
  !acc

(* Heckbert's k < 0: no refracted ray at this relative index and cosine *)
let[@inline] total_internal eta cos_i = eta > 1. && 1. +. (eta *. eta *. ((cos_i *. cos_i) -. 1.)) < 0.

(* [media]: the interiors the ray is inside, innermost first. *)
let rec trace_ray ?(tmin = Ray.epsilon) (s : Scene.t) (ray : Ray.t) level weight media =
  if level > s.settings.max_trace_level || weight < s.settings.adc_bailout then black
  else
    match Scene.intersect s ray tmin infinity with
    | None ->
        if Sky.is_empty s.sky then s.background
        else Sky.eval s.sky ~background:s.background (Vec3.normalize ray.dir)
    | Some hit ->
        (* POV-Ray fades what comes through the far side of a medium, not
           the far surface's own shading *)
        let fade = match media with (i : Interior.t) :: _ -> Interior.fade i hit.t | [] -> white in
        shade s ray hit level weight media fade

and shade s ray hit level weight media fade =
  let d = ray.dir in
  let entering = Vec3.dot hit.normal d < 0. in
  let n0 = if entering then hit.normal else Vec3.neg hit.normal in
  let p = hit.point in
  (* relative index of refraction across this surface *)
  let inner = hit.obj.interior in
  let outer_ior = match media with i :: _ -> i.Interior.ior | [] -> 1. in
  (* entering or leaving is decided as POV-Ray does, by whether the ray is
     already inside this interior, not by the side of the surface: the
     children of a CSG share their parent's interior, so in the overlap of
     a union of glass spheres the inner walls bend light as glass/air *)
  let eta, next_media =
    if not (List.memq inner media) then (outer_ior /. inner.ior, inner :: media)
    else
      let rest = match media with i :: r when i == inner -> r | m -> List.filter (fun i -> i != inner) m in
      let beyond = match rest with i :: _ -> i.Interior.ior | [] -> 1. in
      (inner.ior /. beyond, rest)
  in
  let top_normal = ref None in
  let bailout = s.settings.adc_bailout in
  (* guessed from the unperturbed normal; shaded again in the rare case
     the top layer's normal or an opaque texture says otherwise *)
  let guess = total_internal eta (-.Vec3.dot d n0) in
  let c, tr =
    layers s d p n0 level weight media eta top_normal (not guess) black white hit.obj.texture
  in
  let n = Option.value ~default:n0 !top_normal in
  let c, tr =
    if guess = (Color.luminance tr > bailout && total_internal eta (-.Vec3.dot d n)) then (c, tr)
    else begin
      top_normal := None;
      layers s d p n0 level weight media eta top_normal guess black white hit.obj.texture
    end
  in
  if Color.luminance tr <= bailout then c
  else
    let w = weight *. Color.max_channel tr in
    if eta = 1. then
      (* same index on both sides: straight through, no trace level used *)
      add c (mul (mul tr fade) (trace_ray s (Ray.make p d) level w next_media))
    else
      let cos_i = -.Vec3.dot d n in
      let k = 1. +. (eta *. eta *. ((cos_i *. cos_i) -. 1.)) in
      if k < 0. then
        (* total internal reflection: not filtered by the surface colour *)
        add c (mul fade (trace_ray s (Ray.make p (Vec3.madd d (2. *. cos_i) n)) (level + 1) weight media))
      else
        let t = Vec3.madd (Vec3.scale eta d) ((eta *. cos_i) -. Float.sqrt k) n in
        add c (mul (mul tr fade) (trace_ray s (Ray.make p t) (level + 1) w next_media))

(* Shade the layers of a texture top down; [w] is what the layers above
   let through; returns the colour and what the whole texture lets
   through, and sets [top_normal] to the top layer's normal. [refl]: add
   the finishes' reflection (POV-Ray leaves it out where the light passing
   through is totally reflected inside: the TIR ray stands for it). A
   function of its own, not a closure in [shade]: it runs for every hit. *)
and layers s d p n0 level weight media eta top_normal refl acc w = function
  | [] -> (acc, w)
  | (layer : Texture.layer) :: rest -> (
      match layer.tmap with
      | Some m ->
          (* a patterned layer: blend the textures around the value *)
          let c, f =
            List.fold_left
              (fun (c, f) (k, t) ->
                let c', f' =
                  layers s d p n0 level weight media eta top_normal refl black white t
                in
                (madd c k c', madd f k f'))
              (black, black) (Texture.blend m p)
          in
          let acc = add acc (mul w c) and w = mul w f in
          if is_black w then (acc, w)
          else layers s d p n0 level weight media eta top_normal refl acc w rest
      | None ->
          let n =
            match layer.normal with
            | None -> n0
            | Some nm ->
                let m = Normal.perturb nm p n0 in
                if Vec3.dot m d > 0. then Vec3.madd m (-2. *. Vec3.dot m d) d |> Vec3.normalize
                else m
          in
          if !top_normal = None then top_normal := Some n;
          let f = layer.finish in
          let pig = Pigment.eval layer.pigment p in
          let pc = pig.c in
          let alpha =
            if s.Scene.settings.legacy_alpha then
              1. -. ((pig.filter *. Color.max_channel pc) +. pig.transmit)
            else 1. -. pig.filter -. pig.transmit
          in
          let local =
            madd (direct s f pc alpha p n d) alpha
              (mul pc (add (mul f.ambient s.settings.ambient_light) f.emission))
          in
          let local =
            if refl then add local (reflection s f pc n d p level (weight *. max_channel w) media eta)
            else local
          in
          let acc = add acc (mul w local) in
          let w = mul w (add (scale pig.filter pc) (gray pig.transmit)) in
          if is_black w then (acc, w)
          else layers s d p n0 level weight media eta top_normal refl acc w rest)

and reflection s (f : Finish.t) pc n d p level weight media eta =
  if not (Finish.has_reflection f) then black
  else
    let rf = f.reflection in
    let cos_i = -.Vec3.dot d n in
    let kr, w =
      let span = add rf.rmax (scale (-1.) rf.rmin) in
      if rf.fresnel then
        let k = if eta = 1. then 0. else fresnel (1. /. eta) cos_i in
        let kr = add rf.rmin (scale k span) in
        (kr, max_channel kr)
      else
        let k = Float.pow (1. -. cos_i) rf.falloff in
        (add rf.rmin (scale k span), Float.max (max_channel rf.rmin) (max_channel rf.rmax))
    in
    let kr = mul kr (metallic_tint rf.rmetallic cos_i pc) in
    if is_black kr then black
    else
      let dir = Vec3.madd d (2. *. cos_i) n in
      let rc = trace_ray s (Ray.make p dir) (level + 1) (weight *. w) media in
      let rc = if rf.exponent = 1. then rc else Color.pow rc (1. /. rf.exponent) in
      mul kr rc

(* POV-Ray starts camera rays inside every object that contains the
   camera (the last one in the scene first). Cached per scene and origin:
   the camera location is the same for every ray of a pinhole camera. *)
let start_cache : (Scene.t * Vec3.t * Interior.t list) option Atomic.t = Atomic.make None

let start_media (s : Scene.t) (o : Vec3.t) =
  match Atomic.get start_cache with
  | Some (s', o', m) when s' == s && o' = o -> m
  | _ ->
      let m =
        Array.fold_left
          (fun acc (obj : Object.t) -> if Object.inside obj o then obj.interior :: acc else acc)
          [] s.objects
      in
      Atomic.set start_cache (Some (s, o, m));
      m

let trace s (ray : Ray.t) = trace_ray ~tmin:0. s ray 1 1. (start_media s ray.origin)

(* Focal blur (camera aperture > 0): the mean of [blur_samples] rays
   through points of the lens, stratified by a Hammersley set turned by
   a per-pixel offset (POV-Ray picks its lens points at random and stops
   early by a confidence test, so blurred parts agree in the mean, not
   pixel for pixel). *)
let radical_inverse k =
  let rec go k f acc = if k = 0 then acc else go (k lsr 1) (f *. 0.5) (if k land 1 = 1 then acc +. f else acc) in
  go k 0.5 0.

let focal_blur (s : Scene.t) sx sy px py =
  let cam = s.camera in
  let n = if cam.blur_samples > 0 then cam.blur_samples else 10 (* camlray's default *) in
  let key = (int_of_float (Float.floor py) * 65599) + int_of_float (Float.floor px) in
  let sampler = Sampler.create ~seed:0 ~pixel:key ~sample:0 in
  let du = Sampler.get sampler 0 and dv = Sampler.get sampler 1 in
  let acc = ref black in
  for k = 0 to n - 1 do
    let u = Float.rem (((float_of_int k +. 0.5) /. float_of_int n) +. du) 1. in
    let v = Float.rem (radical_inverse k +. dv) 1. in
    acc := add !acc (trace s (Camera.ray_lens cam sx sy u v))
  done;
  scale (1. /. float_of_int n) !acc

let sample (s : Scene.t) ~width ~height px py =
  let sx, sy = Camera.pixel_coords ~width ~height px py in
  if s.camera.aperture > 0. then focal_blur s sx sy px py else trace s (Camera.ray s.camera sx sy)

let pixel s ~width ~height x y =
  sample s ~width ~height (float_of_int x +. 0.5) (float_of_int y +. 0.5)
