open Color

(* if-based min/max: Float.min/max order NaN and -0 through a C call *)
let fmin = Floats.fmin
let fmax = Floats.fmax

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

let k_lambert = 0 and k_mirror = 1 and k_phong = 2 and k_blinn = 3 and k_glossy = 4 and k_glass = 5
let[@inline] max3 r g b = fmax r (fmax g b)

(* A lobe's weight from its kind, colour [(r, g, b)] (glass: transmit),
   glass's reflect [(r2, g2, b2)] and exponent [e] *)
let[@inline] weight_of kind r g b r2 g2 b2 e =
  if kind = k_phong then 2. *. max3 r g b /. (e +. 1.)
  else if kind = k_blinn then 8. *. max3 r g b /. (e +. 1.)
  else if kind = k_glass then fmax (max3 r2 g2 b2) (max3 r g b)
  else max3 r g b

let weight = function
  | Lambert a -> weight_of k_lambert a.r a.g a.b 0. 0. 0. 0.
  | Mirror c -> weight_of k_mirror c.r c.g c.b 0. 0. 0. 0.
  | Phong { k; exponent } -> weight_of k_phong k.r k.g k.b 0. 0. 0. exponent
  | Blinn { k; exponent } -> weight_of k_blinn k.r k.g k.b 0. 0. 0. exponent
  | Glossy { color; _ } -> weight_of k_glossy color.r color.g color.b 0. 0. 0. 0.
  | Glass { reflect; transmit; _ } ->
      weight_of k_glass transmit.r transmit.g transmit.b reflect.r reflect.g reflect.b 0.

let clamp01 x = fmin 1. (fmax 0. x)

(* No reflection, highlight or metal: a matte surface (most of a Monte
   Carlo scene's hits) *)
let plain_diffuse (f : Finish.t) =
  let zero (c : Color.t) = c.r = 0. && c.g = 0. && c.b = 0. in
  f.specular = 0. && f.phong = 0. && f.metallic = 0. && f.reflection.rmetallic = 0.
  && zero f.reflection.rmin && zero f.reflection.rmax

(* The lobes written in place: kind, weight, colours and exponent of up
   to five lobes in flat arrays, filled at each path vertex without
   allocating. *)
let max_lobes = 5

type lobes = {
  mutable count : int;
  kind : int array;
  w : Float.Array.t;  (** weight *)
  c : Float.Array.t;  (** 3 per lobe: albedo, colour, k, or glass's transmit *)
  c2 : Float.Array.t;  (** 3 per lobe: glass's reflect *)
  e : Float.Array.t;  (** exponent, or glass's eta *)
  em : Color.acc;  (** emission *)
  pig : Pigment.out;  (** the pigment at the point *)
  mutable bumped : bool;  (** the lobes are seen about [ns], not the surface's normal *)
  ns : Vec3.m;  (** the shading normal, when [bumped] *)
  mw : Vec3.m;  (** {!Bsdf}'s: a direction mirrored about the surface *)
}

let lobes () =
  { count = 0; kind = Array.make max_lobes 0; w = Float.Array.make max_lobes 0.;
    c = Float.Array.make (3 * max_lobes) 0.; c2 = Float.Array.make (3 * max_lobes) 0.;
    e = Float.Array.make max_lobes 0.; em = Color.acc 0.; pig = Pigment.out (); bumped = false;
    ns = Vec3.m (); mw = Vec3.m () }

let fset = Float.Array.unsafe_set
let fget = Float.Array.unsafe_get
(* a lobe added when its weight is positive *)
let[@inline] push m kind r g b r2 g2 b2 e =
  let w = weight_of kind r g b r2 g2 b2 e in
  if w > 0. then begin
    let i = m.count in
    Array.unsafe_set m.kind i kind;
    fset m.w i w;
    fset m.c (3 * i) r;
    fset m.c ((3 * i) + 1) g;
    fset m.c ((3 * i) + 2) b;
    fset m.c2 (3 * i) r2;
    fset m.c2 ((3 * i) + 1) g2;
    fset m.c2 ((3 * i) + 2) b2;
    fset m.e i e;
    m.count <- i + 1
  end

let load_lobe m (l : lobe) =
  match l with
  | Lambert a -> push m k_lambert a.r a.g a.b 0. 0. 0. 0.
  | Mirror a -> push m k_mirror a.r a.g a.b 0. 0. 0. 0.
  | Phong { k; exponent } -> push m k_phong k.r k.g k.b 0. 0. 0. exponent
  | Blinn { k; exponent } -> push m k_blinn k.r k.g k.b 0. 0. 0. exponent
  | Glossy { color; exponent } -> push m k_glossy color.r color.g color.b 0. 0. 0. exponent
  | Glass { eta; reflect; transmit } ->
      push m k_glass transmit.r transmit.g transmit.b reflect.r reflect.g reflect.b eta

let load m (t : t) =
  m.count <- 0;
  m.bumped <- false;
  Array.iter (load_lobe m) t.lobes;
  Color.acc_set m.em t.emission.r t.emission.g t.emission.b

let lobe m i =
  let col a = Color.make (fget a (3 * i)) (fget a ((3 * i) + 1)) (fget a ((3 * i) + 2)) in
  let e = fget m.e i in
  match Array.unsafe_get m.kind i with
  | 0 -> Lambert (col m.c)
  | 1 -> Mirror (col m.c)
  | 2 -> Phong { k = col m.c; exponent = e }
  | 3 -> Blinn { k = col m.c; exponent = e }
  | 4 -> Glossy { color = col m.c; exponent = e }
  | _ -> Glass { eta = e; reflect = col m.c2; transmit = col m.c }

(* A texture_map's or block pattern's texture at [p]: the entry the
   pattern picks, the heavier of two blended ones; an average's or a
   blob's components' heaviest (nested maps in turn) *)
let pick_key = Scratch.key Texture.pick

(* Per domain: where the texture [resolve] found is taken (the point
   the maps above it passed on, see {!Texture.blend_m}) and the frames of
   those maps, outermost first, [nchain] of them (its normal is perturbed
   in the innermost one's space, as POV-Ray 3.7 does) *)
type resolved = { rp : Vec3.m; mutable chain : Transform.t array; mutable nchain : int; rn : Vec3.m }

let resolved_key = Scratch.key (fun () -> { rp = Vec3.m (); chain = [||]; nchain = 0; rn = Vec3.m () })

let chain_push r t =
  let n = r.nchain in
  if n = Array.length r.chain then r.chain <- Array.append r.chain (Array.make (Int.max 4 n) t);
  Array.unsafe_set r.chain n t;
  r.nchain <- n + 1

let rec resolve_in r (tex : Texture.t) (p : Vec3.m) =
  match tex with
  | { Texture.tmap = Some m; _ } :: _ ->
      let pk = Scratch.get pick_key in
      Texture.blend_m m p pk;
      Vec3.set r.rp pk.tp.mx pk.tp.my pk.tp.mz;
      (match m.kind with
      | Texture.Field _ -> ()
      | Texture.Map | Texture.Average -> if not (Transform.is_identity m.frame) then chain_push r m.frame);
      resolve_in r (Texture.heaviest m pk) r.rp
  | _ -> tex

let resolve (tex : Texture.t) (p : Vec3.m) =
  let r = Scratch.get resolved_key in
  r.nchain <- 0;
  Vec3.set r.rp p.mx p.my p.mz;
  resolve_in r tex r.rp

(* [nm] perturbs [n] at the resolved point, in the frames of the maps
   above it, into [out] *)
let perturb_resolved nm (n : Vec3.m) (out : Vec3.m) =
  let r = Scratch.get resolved_key in
  Normal.perturb_through nm r.rp n r.chain r.nchain r.rn out

(* The material of a layer at [p] into [m], as [of_texture] makes it
   (the same arithmetic); inlined where it is called, so that [cos_o]
   is not boxed *)
let[@inline] fill m (layer : Texture.layer) (inter : Interior.t) (p : Vec3.m) cos_o entering =
  m.count <- 0;
  let f = layer.finish in
  let pig = m.pig in
  Pigment.into layer.pigment p pig;
  let tr = clamp01 (pig.filter +. pig.transmit) in
  let alpha = 1. -. tr in
  let refracts = tr > 0. && inter.ior <> 1. in
  Color.acc_set m.em (alpha *. (pig.r *. f.emission.r)) (alpha *. (pig.g *. f.emission.g))
    (alpha *. (pig.b *. f.emission.b));
  (* the opaque part *)
  let d = alpha *. f.diffuse in
  let lr = d *. pig.r and lg = d *. pig.g and lb = d *. pig.b in
  push m k_lambert lr lg lb 0. 0. 0. 0.;
  (* a matte surface (most hits) has no other lobe of positive weight *)
  if tr > 0. || not (plain_diffuse f) then begin
    let metal = f.metallic > 0. || f.reflection.rmetallic > 0. in
    (* [reflectivity], tinted for metals ([tint 1.]), scaled by alpha
       where the glass part's Fresnel replaces it *)
    let r = f.reflection in
    let t = if r.fresnel then Finish.fresnel inter.ior cos_o else Float.pow (fmax 0. (1. -. cos_o)) r.falloff in
    let kx = r.rmin.r +. (t *. (r.rmax.r +. (-1. *. r.rmin.r)))
    and ky = r.rmin.g +. (t *. (r.rmax.g +. (-1. *. r.rmin.g)))
    and kz = r.rmin.b +. (t *. (r.rmax.b +. (-1. *. r.rmin.b))) in
    let mk = if metal then Finish.metallic_k 1. cos_o else 0. in
    let kx = if metal then kx *. (1. +. (mk *. (pig.r -. 1.))) else kx
    and ky = if metal then ky *. (1. +. (mk *. (pig.g -. 1.))) else ky
    and kz = if metal then kz *. (1. +. (mk *. (pig.b -. 1.))) else kz in
    let kx = if refracts then alpha *. kx else kx
    and ky = if refracts then alpha *. ky else ky
    and kz = if refracts then alpha *. kz else kz in
    (* conserve_energy: the transparent part cut by what the mirror
       reflects, 1 - its weight per channel, as whitted mode cuts it by
       1 - reflectivity; where the glass's Fresnel stands for the
       reflection (a clear refracting surface) nothing is cut. Not below
       0: POV-Ray takes light away where the reflectivity passes 1, a
       path's weight stays positive. *)
    let cr = if f.conserve_energy then clamp01 (1. -. kx) else 1.
    and cg = if f.conserve_energy then clamp01 (1. -. ky) else 1.
    and cb = if f.conserve_energy then clamp01 (1. -. kz) else 1. in
    (* [tint f.metallic cos_o pig] for the highlights *)
    let plainh = f.metallic = 0. in
    let hk = if plainh then 0. else Finish.metallic_k f.metallic cos_o in
    let hr = if plainh then 1. else 1. +. (hk *. (pig.r -. 1.))
    and hg = if plainh then 1. else 1. +. (hk *. (pig.g -. 1.))
    and hb = if plainh then 1. else 1. +. (hk *. (pig.b -. 1.)) in
    if metal && f.specular > 0. && not (kx = 0. && ky = 0. && kz = 0.) then
      (* a rough metal: the highlight is the blurred reflection *)
      push m k_glossy kx ky kz 0. 0. 0. (1. /. f.roughness)
    else begin
      push m k_mirror kx ky kz 0. 0. 0. 0.;
      let s = f.specular and e = 1. /. f.roughness in
      let br = s *. hr and bg = s *. hg and bb = s *. hb in
      push m k_blinn br bg bb 0. 0. 0. e
    end;
    let ph = f.phong and e = f.phong_size in
    let pr = ph *. hr and pg = ph *. hg and pb = ph *. hb in
    push m k_phong pr pg pb 0. 0. 0. e;
    (* the transparent part *)
    if tr > 0. then begin
      let tr_r = cr *. ((pig.filter *. pig.r) +. pig.transmit)
      and tr_g = cg *. ((pig.filter *. pig.g) +. pig.transmit)
      and tr_b = cb *. ((pig.filter *. pig.b) +. pig.transmit) in
      let eta = if refracts then if entering then 1. /. inter.ior else inter.ior else 1. in
      push m k_glass tr_r tr_g tr_b tr tr tr eta
    end
  end

(* The least cosine a shading normal keeps with the surface's normal and
   with the viewer *)
let face_min = 0.01

(* The shading normal [ns] turned toward the half vector h of [n] and
   [wo] (h.n = h.wo = |n + wo| / 2, at least 0.707), just far enough
   along the chord that its cosines with both are at least [face_min]:
   unchanged where they already are. *)
let face (ns : Vec3.m) (n : Vec3.m) (wo : Vec3.m) =
  let a = Vec3.dot_m ns n and b = Vec3.dot_m ns wo in
  if a < face_min || b < face_min then begin
    let hx = n.mx +. wo.mx and hy = n.my +. wo.my and hz = n.mz +. wo.mz in
    let l = Float.sqrt ((hx *. hx) +. (hy *. hy) +. (hz *. hz)) in
    let c = 0.5 *. l in
    let ta = if a < face_min then (face_min -. a) /. (c -. a) else 0.
    and tb = if b < face_min then (face_min -. b) /. (c -. b) else 0. in
    let t = fmin 1. (fmax ta tb) in
    let s = 1. -. t and k = t /. l in
    Vec3.set ns ((s *. ns.mx) +. (k *. hx)) ((s *. ns.my) +. (k *. hy)) ((s *. ns.mz) +. (k *. hz));
    Vec3.normalize_m ns
  end

(* The shading normal is the normal of the layer the lobes come from:
   POV-Ray lights each layer of a layered texture with that layer's own
   normal, and the lobes here are the top layer's (of the texture_map
   entry [resolve] picks), so its pigment, finish and normal stay
   together. *)
let into m tex inter (p : Vec3.m) (n : Vec3.m) (wo : Vec3.m) ~entering =
  match resolve tex p with
  | [] ->
      m.count <- 0;
      m.bumped <- false;
      Color.acc_set m.em 0. 0. 0.
  | (layer : Texture.layer) :: _ -> (
      let tp = (Scratch.get resolved_key).rp in
      match layer.normal with
      | None ->
          m.bumped <- false;
          fill m layer inter tp ((n.mx *. wo.mx) +. (n.my *. wo.my) +. (n.mz *. wo.mz)) entering
      | Some nm ->
          let ns = m.ns in
          perturb_resolved nm n ns;
          face ns n wo;
          m.bumped <- true;
          fill m layer inter tp ((ns.mx *. wo.mx) +. (ns.my *. wo.my) +. (ns.mz *. wo.mz)) entering)

let of_lobes m = { lobes = Array.init m.count (lobe m); emission = Color.of_acc m.em }

let of_texture (tex : Texture.t) (inter : Interior.t) (p : Vec3.t) ~cos_o ~entering =
  let m = lobes () and pm = Vec3.m () in
  Vec3.load pm p;
  (match resolve tex pm with
  | [] -> Color.acc_set m.em 0. 0. 0.
  | layer :: _ -> fill m layer inter (Scratch.get resolved_key).rp cos_o entering);
  of_lobes m
