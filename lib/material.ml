open Color

(* if-based min/max: Float.min/max order NaN and -0 through a C call *)
let[@inline] fmax (a : float) b = if a >= b then a else b
let[@inline] fmin (a : float) b = if a <= b then a else b
let[@inline] maxc (c : Color.t) = fmax c.r (fmax c.g c.b)

type lobe =
  | Lambert of Color.t
  | Mirror of Color.t
  | Phong of { k : Color.t; exponent : float }
  | Blinn of { k : Color.t; exponent : float }
  | Glossy of { color : Color.t; exponent : float }
  | Glass of { eta : float; reflect : Color.t; transmit : Color.t }

type t = { lobes : lobe array; emission : Color.t }

let black = { lobes = [||]; emission = Color.black }

let is_delta = function
  | Mirror _ | Glass _ -> true
  | Lambert _ | Phong _ | Blinn _ | Glossy _ -> false

let weight = function
  | Lambert a -> maxc a
  | Mirror c -> maxc c
  | Phong { k; exponent } -> 2. *. maxc k /. (exponent +. 1.)
  | Blinn { k; exponent } -> 8. *. maxc k /. (exponent +. 1.)
  | Glossy { color; _ } -> maxc color
  | Glass { reflect; transmit; _ } -> fmax (maxc reflect) (maxc transmit)

(* Unpolarised Fresnel reflectance for a relative index n = n_t / n_i
   (POV-Ray's formula, pov-facts 5.5); 1 past the critical angle. *)
let fresnel_pov n c =
  let g2 = (n *. n) +. (c *. c) -. 1. in
  if g2 <= 0. then 1.
  else
    let g = Float.sqrt g2 in
    let a = (g -. c) /. (g +. c) and b = ((c *. (g +. c)) -. 1.) /. ((c *. (g -. c)) +. 1.) in
    0.5 *. a *. a *. (1. +. (b *. b))

(* POV-Ray's metallic factor F, x = angle / 90 degrees. *)
let metallic_f c =
  let x = Float.acos (fmin 1. (Float.abs c)) /. (Float.pi /. 2.) in
  fmin 1. (fmax 0. ((0.014567225 /. ((x -. 1.12) ** 2.)) -. 0.011612903))

let tint m c (p : Color.t) =
  if m = 0. then white
  else
    let k = m *. (1. -. metallic_f c) in
    make (1. +. (k *. (p.r -. 1.))) (1. +. (k *. (p.g -. 1.))) (1. +. (k *. (p.b -. 1.)))

(* POV-Ray's reflection amount Kr at the viewing cosine c. *)
let reflectivity (r : Finish.reflection) ior c =
  let t =
    if r.fresnel then fresnel_pov ior c else Float.pow (fmax 0. (1. -. c)) r.falloff
  in
  add r.rmin (scale t (add r.rmax (scale (-1.) r.rmin)))

let clamp01 x = fmin 1. (fmax 0. x)

(* No reflection, highlight or metal: a matte surface (most of a Monte
   Carlo scene's hits) *)
let plain_diffuse (f : Finish.t) =
  let zero (c : Color.t) = c.r = 0. && c.g = 0. && c.b = 0. in
  f.specular = 0. && f.phong = 0. && f.metallic = 0. && f.reflection.rmetallic = 0.
  && zero f.reflection.rmin && zero f.reflection.rmax

(* At most five lobes: literal arrays are allocated inline, where
   Array.of_list calls the runtime. *)
let of_rev_list = function
  | [] -> [||]
  | [ a ] -> [| a |]
  | [ b; a ] -> [| a; b |]
  | [ c; b; a ] -> [| a; b; c |]
  | [ d; c; b; a ] -> [| a; b; c; d |]
  | l -> Array.of_list (List.rev l)

let of_texture (tex : Texture.t) (inter : Interior.t) p ~cos_o ~entering =
  match tex with
  | [] -> black
  | (layer : Texture.layer) :: _ ->
      let f = layer.finish in
      let pc = Pigment.eval layer.pigment p in
      let pig = pc.c in
      let tr = clamp01 (pc.filter +. pc.transmit) in
      let alpha = 1. -. tr in
      let refracts = tr > 0. && inter.ior <> 1. in
      if (not (tr > 0.)) && plain_diffuse f then
        (* every lobe but the diffuse one has weight 0 here, whatever the
           angle: the same material, without computing them *)
        let l = Lambert (scale (alpha *. f.diffuse) pig) in
        { lobes = (if weight l > 0. then [| l |] else [||]); emission = scale alpha (mul pig f.emission) }
      else
      (* at most five lobes, kept in order when their weight is positive *)
      let lobes = ref [] in
      let push l = if weight l > 0. then lobes := l :: !lobes in
      (* the opaque part *)
      push (Lambert (scale (alpha *. f.diffuse) pig));
      let metal = f.metallic > 0. || f.reflection.rmetallic > 0. in
      (* metals: reflection tinted by the pigment, whitening at grazing
         angles as POV's metallic factor does *)
      let kr = reflectivity f.reflection inter.ior cos_o in
      let kr = if metal then mul kr (tint 1. cos_o pig) else kr in
      (* exact Fresnel on the glass part replaces POV's reflection there *)
      let kr = if refracts then scale alpha kr else kr in
      let htint = tint f.metallic cos_o pig in
      if metal && f.specular > 0. && not (is_black kr) then
        (* a rough metal: the highlight is the blurred reflection *)
        push (Glossy { color = kr; exponent = 1. /. f.roughness })
      else begin
        push (Mirror kr);
        push (Blinn { k = scale f.specular htint; exponent = 1. /. f.roughness })
      end;
      push (Phong { k = scale f.phong htint; exponent = f.phong_size });
      (* the transparent part *)
      if tr > 0. then begin
        let transmit = add (scale pc.filter pig) (gray pc.transmit) in
        let eta = if refracts then (if entering then 1. /. inter.ior else inter.ior) else 1. in
        push (Glass { eta; reflect = gray tr; transmit })
      end;
      { lobes = of_rev_list !lobes; emission = scale alpha (mul pig f.emission) }
