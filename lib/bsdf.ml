open Color

(* if-based min/max: Float.min/max order NaN and -0 through a C call *)
let fmin = Floats.fmin
let fmax = Floats.fmax

let inv_pi = 1. /. Float.pi

(* Duff et al. 2017 *)
let basis (n : Vec3.t) =
  let sign = Float.copy_sign 1. n.z in
  let a = -1. /. (sign +. n.z) in
  let b = n.x *. n.y *. a in
  ( Vec3.make (1. +. (sign *. n.x *. n.x *. a)) (sign *. b) (-.sign *. n.x),
    Vec3.make b (sign +. (n.y *. n.y *. a)) (-.n.y) )

(* [around (x, y, z) cos_t phi] into [out] *)
let[@inline] around_into (out : Vec3.m) nx ny nz cos_t phi =
  let sin_t = Float.sqrt (fmax 0. (1. -. (cos_t *. cos_t))) in
  let sign = if nz > 0. || (nz = 0. && 1. /. nz > 0.) then 1. else -1. in
  let a = -1. /. (sign +. nz) in
  let b = nx *. ny *. a in
  let tx = 1. +. (sign *. nx *. nx *. a) and ty = sign *. b and tz = -.sign *. nx in
  let bx = b and by = sign +. (ny *. ny *. a) and bz = -.ny in
  let kt = sin_t *. Float.cos phi and kb = sin_t *. Float.sin phi in
  Vec3.set out
    ((kt *. tx) +. (kb *. bx) +. (cos_t *. nx))
    ((kt *. ty) +. (kb *. by) +. (cos_t *. ny))
    ((kt *. tz) +. (kb *. bz) +. (cos_t *. nz))

let cosine_hemisphere (n : Vec3.t) u1 u2 =
  let out = Vec3.m () in
  around_into out n.x n.y n.z (Float.sqrt (1. -. u1)) (2. *. Float.pi *. u2);
  Vec3.of_m out

let[@inline] fresnel eta ci =
  let ci = fmin 1. (Float.abs ci) in
  let s2 = eta *. eta *. (1. -. (ci *. ci)) in
  if s2 >= 1. then 1.
  else
    let ct = Float.sqrt (1. -. s2) in
    let rs = ((eta *. ci) -. ct) /. ((eta *. ci) +. ct) in
    let rp = (ci -. (eta *. ct)) /. (ci +. (eta *. ct)) in
    0.5 *. ((rs *. rs) +. (rp *. rp))

(* In place: lobes in a {!Material.lobes}, vectors in {!Vec3.m}, results
   in the caller's records. The helpers are inlined so that the floats
   they pass and return stay unboxed; the arithmetic is that of the
   vector forms ([reflect], [half], [around]) term for term. *)

let dot = Vec3.dot_m

(* [reflect wo (x, y, z)] into [out] *)
let[@inline] reflect_into (out : Vec3.m) (wo : Vec3.m) x y z =
  let k = 2. *. ((wo.mx *. x) +. (wo.my *. y) +. (wo.mz *. z)) in
  Vec3.set out ((-.wo.mx) +. (k *. x)) ((-.wo.my) +. (k *. y)) ((-.wo.mz) +. (k *. z))

(* [dot (reflect wo n) wi] *)
let[@inline] reflect_dot (wo : Vec3.m) (n : Vec3.m) (wi : Vec3.m) =
  let k = 2. *. dot wo n in
  (((-.wo.mx) +. (k *. n.mx)) *. wi.mx) +. (((-.wo.my) +. (k *. n.my)) *. wi.my)
  +. (((-.wo.mz) +. (k *. n.mz)) *. wi.mz)

(* density of a direction around [axis] with (e+1)/(2 pi) cos^e *)
let[@inline] lobe_pdf e c = if c <= 0. then 0. else (e +. 1.) *. 0.5 *. inv_pi *. Float.pow c e

(* [half wo wi] as a unit vector, then [dot n h] ([~oh:false]) or the
   density of wi through a half-vector lobe of exponent [e] ([~oh:true]) *)
let[@inline] half_use ~oh e (n : Vec3.m) (wo : Vec3.m) (wi : Vec3.m) =
  let hx = wo.mx +. wi.mx and hy = wo.my +. wi.my and hz = wo.mz +. wi.mz in
  let l = Float.sqrt ((hx *. hx) +. (hy *. hy) +. (hz *. hz)) in
  let k = 1. /. l in
  let hx = if l > 0. then k *. hx else hx and hy = if l > 0. then k *. hy else hy
  and hz = if l > 0. then k *. hz else hz in
  let nh = (n.mx *. hx) +. (n.my *. hy) +. (n.mz *. hz) in
  if not oh then nh
  else
    let o = (wo.mx *. hx) +. (wo.my *. hy) +. (wo.mz *. hz) in
    if o <= 0. then 0. else lobe_pdf e nh /. (4. *. o)

let fget = Float.Array.unsafe_get

(* A lobe's f is a scalar times the lobe's colour: [lobe_k] is the scalar
   (0 for deltas and below the surface), so that sums over lobes need no
   colour per lobe. *)
let[@inline] lobe_k (m : Material.lobes) i n wo wi =
  let ci = dot n wi in
  if ci <= 0. then 0.
  else
    let kind = Array.unsafe_get m.kind i and e = fget m.e i in
    if kind = Material.k_lambert then inv_pi
    else if kind = Material.k_phong then
      let c = reflect_dot wo n wi in
      if c <= 0. then 0. else Float.pow c e *. inv_pi /. ci
    else if kind = Material.k_blinn then
      let c = half_use ~oh:false e n wo wi in
      if c <= 0. then 0. else Float.pow c e *. inv_pi /. ci
    else if kind = Material.k_glossy then half_use ~oh:true e n wo wi /. ci
    else 0.

let[@inline] lobe_pdf_of (m : Material.lobes) i n wo wi =
  let kind = Array.unsafe_get m.kind i and e = fget m.e i in
  if kind = Material.k_lambert then fmax 0. (dot n wi) *. inv_pi
  else if kind = Material.k_phong then lobe_pdf e (reflect_dot wo n wi)
  else if kind = Material.k_blinn || kind = Material.k_glossy then half_use ~oh:true e n wo wi
  else 0.

let[@inline] total (m : Material.lobes) =
  let s = ref 0. in
  for i = 0 to m.count - 1 do
    s := !s +. fget m.w i
  done;
  !s

(* Shading normals ([m.bumped]: the texture has a [normal]). The lobes
   are those of a surface facing [m.ns] ({!Material.face}d), set on a
   surface whose normal is [n]; a direction they send to the wrong side
   of the surface (below it when reflected, above it when refracted) is
   mirrored about the surface's plane back to the right side. Nothing
   leaks through the surface, nothing is lost: with fc the lobes' f
   times the cosine about [ns], and M the mirror about the plane, the
   material's f cos about [n] at wi above the surface is
   fc (wi) + fc (M wi), and the density of wi is p (wi) + p (M wi) (both
   mirror images lead there). Over the hemisphere above [n] that is
   what the lobes give over the whole sphere: a white Lambertian surface
   reflects all the light it receives, however tilted [ns] is, and each
   sample of it weighs exactly its albedo. The sides (entering, above or
   below) are the surface's, [n]'s. Without [bumped], the code is what
   it was before shading normals. *)

(* [w] mirrored about the plane through the origin normal to [n], into
   [out] *)
let[@inline] mirror_into (out : Vec3.m) (w : Vec3.m) (n : Vec3.m) =
  let k = -2. *. dot w n in
  Vec3.set out (w.mx +. (k *. n.mx)) (w.my +. (k *. n.my)) (w.mz +. (k *. n.mz))

(* [w] mirrored to [n]'s side of the plane ([up]) or to the other side,
   where it is not already there *)
let[@inline] fold (w : Vec3.m) (n : Vec3.m) up =
  let c = dot w n in
  if (up && c < 0.) || ((not up) && c > 0.) then mirror_into w w n

(* The lobes' fc (wi) + fc (mw), per channel, into [out] *)
let fc_into (m : Material.lobes) ns wo wi mw (out : Color.acc) =
  let r = ref 0. and g = ref 0. and b = ref 0. in
  for i = 0 to m.count - 1 do
    let k = (lobe_k m i ns wo wi *. dot ns wi) +. (lobe_k m i ns wo mw *. dot ns mw) in
    r := !r +. (k *. fget m.c (3 * i));
    g := !g +. (k *. fget m.c ((3 * i) + 1));
    b := !b +. (k *. fget m.c ((3 * i) + 2))
  done;
  Color.acc_set out !r !g !b

let eval_bumped (m : Material.lobes) n wo wi (out : Color.acc) =
  let ci = dot n wi in
  if ci <= 0. then Color.acc_set out 0. 0. 0.
  else begin
    mirror_into m.mw wi n;
    fc_into m m.ns wo wi m.mw out;
    let k = 1. /. ci in
    Color.acc_set out (k *. out.ar) (k *. out.ag) (k *. out.ab)
  end

let eval_plain (m : Material.lobes) n wo wi (out : Color.acc) =
  let r = ref 0. and g = ref 0. and b = ref 0. in
  for i = 0 to m.count - 1 do
    let k = lobe_k m i n wo wi in
    if k <> 0. then begin
      r := !r +. (k *. fget m.c (3 * i));
      g := !g +. (k *. fget m.c ((3 * i) + 1));
      b := !b +. (k *. fget m.c ((3 * i) + 2))
    end
    else begin
      (* the sum adds black: +0, as before (keeps -0 sums bit-identical) *)
      r := !r +. 0.;
      g := !g +. 0.;
      b := !b +. 0.
    end
  done;
  Color.acc_set out !r !g !b

let eval_into (m : Material.lobes) n wo wi out =
  if m.bumped then eval_bumped m n wo wi out else eval_plain m n wo wi out

let[@inline] pdf_total (m : Material.lobes) w n wo wi =
  if w <= 0. then 0.
  else begin
    let acc = ref 0. in
    for i = 0 to m.count - 1 do
      acc := !acc +. (fget m.w i /. w *. lobe_pdf_of m i n wo wi)
    done;
    !acc
  end

let[@inline] pdf_bumped (m : Material.lobes) tot n wo wi =
  if dot n wi <= 0. then 0.
  else begin
    mirror_into m.mw wi n;
    pdf_total m tot m.ns wo wi +. pdf_total m tot m.ns wo m.mw
  end

let[@inline] pdf_m (m : Material.lobes) n wo wi =
  if m.bumped then pdf_bumped m (total m) n wo wi else pdf_total m (total m) n wo wi

let has_smooth_m (m : Material.lobes) =
  let r = ref false in
  for i = 0 to m.count - 1 do
    let k = Array.unsafe_get m.kind i in
    if not (k = Material.k_mirror || k = Material.k_glass) then r := true
  done;
  !r

(* the lobe [sample] picks: i with probability weight_i / tot *)
let[@inline] pick (m : Material.lobes) tot u =
  let k = m.count in
  let i = ref 0 and acc = ref 0. and go = ref true in
  while !go do
    let wl = fget m.w !i in
    if !i = k - 1 || u *. tot < !acc +. wl then go := false
    else (
      acc := !acc +. wl;
      incr i)
  done;
  !i

type pdf = { mutable pdf : float }
type sampled = { wi : Vec3.m; weight : Color.acc; p : pdf; mutable delta : bool }

let sampled () = { wi = Vec3.m (); weight = Color.acc 0.; p = { pdf = 0. }; delta = false }

(* the mixture of non-delta lobes at the direction already in [out.wi] *)
let smooth_into (m : Material.lobes) tot n wo (out : sampled) =
  let wi = out.wi in
  let ci = dot n wi in
  ci > 0.
  &&
  let pd = pdf_total m tot n wo wi in
  pd > 0.
  && begin
       eval_into m n wo wi out.weight;
       let k = ci /. pd and f = out.weight in
       Color.acc_set f (k *. f.ar) (k *. f.ag) (k *. f.ab);
       out.p.pdf <- pd;
       out.delta <- false;
       true
     end

let[@inline] delta_into (out : sampled) k (a : Float.Array.t) i =
  Color.acc_set out.weight (k *. fget a (3 * i)) (k *. fget a ((3 * i) + 1)) (k *. fget a ((3 * i) + 2));
  out.p.pdf <- 0.;
  out.delta <- true

(* [sample] into [out], false where it gives [None]: without a shading
   normal *)
let[@inline] sample_plain (m : Material.lobes) (n : Vec3.m) (wo : Vec3.m) u v w (out : sampled) =
  let tot = total m in
  tot > 0.
  &&
  let i = pick m tot u in
  let p = fget m.w i /. tot in
  let kind = Array.unsafe_get m.kind i and e = fget m.e i in
  let wi = out.wi in
  if kind = Material.k_lambert then begin
    around_into wi n.mx n.my n.mz (Float.sqrt (1. -. v)) (2. *. Float.pi *. w);
    smooth_into m tot n wo out
  end
  else if kind = Material.k_phong then begin
    let c = Float.pow v (1. /. (e +. 1.)) in
    reflect_into wi wo n.mx n.my n.mz;
    around_into wi wi.mx wi.my wi.mz c (2. *. Float.pi *. w);
    smooth_into m tot n wo out
  end
  else if kind = Material.k_blinn || kind = Material.k_glossy then begin
    let c = Float.pow v (1. /. (e +. 1.)) in
    around_into wi n.mx n.my n.mz c (2. *. Float.pi *. w);
    reflect_into wi wo wi.mx wi.my wi.mz;
    smooth_into m tot n wo out
  end
  else if kind = Material.k_mirror then begin
    reflect_into wi wo n.mx n.my n.mz;
    delta_into out (1. /. p) m.c i;
    true
  end
  else begin
    (* glass *)
    let ci = dot wo n in
    let fr = fresnel e ci in
    if v < fr then begin
      reflect_into wi wo n.mx n.my n.mz;
      delta_into out (1. /. p) m.c2 i
    end
    else begin
      let s2 = e *. e *. (1. -. (ci *. ci)) in
      let ct = Float.sqrt (fmax 0. (1. -. s2)) in
      (* Heckbert: T = eta D + (eta c - cos_t) n, D = -wo *)
      let k = (e *. ci) -. ct in
      Vec3.set wi ((-.e *. wo.mx) +. (k *. n.mx)) ((-.e *. wo.my) +. (k *. n.my)) ((-.e *. wo.mz) +. (k *. n.mz));
      Vec3.normalize_m wi;
      delta_into out (1. /. p) m.c i
    end;
    true
  end

(* the mixture of non-delta lobes at the direction already in [out.wi],
   with a shading normal *)
let smooth_bumped (m : Material.lobes) tot n wo (out : sampled) =
  let wi = out.wi in
  dot n wi > 0.
  &&
  let mw = m.mw and ns = m.ns in
  mirror_into mw wi n;
  let pd = pdf_total m tot ns wo wi +. pdf_total m tot ns wo mw in
  pd > 0.
  && begin
       let f = out.weight in
       fc_into m ns wo wi mw f;
       let k = 1. /. pd in
       Color.acc_set f (k *. f.ar) (k *. f.ag) (k *. f.ab);
       out.p.pdf <- pd;
       out.delta <- false;
       true
     end

(* [sample_plain]'s directions about the shading normal, folded back to
   the side of the surface they belong on *)
let[@inline] sample_bumped (m : Material.lobes) (n : Vec3.m) (wo : Vec3.m) u v w (out : sampled) =
  let tot = total m in
  tot > 0.
  &&
  let i = pick m tot u in
  let p = fget m.w i /. tot in
  let kind = Array.unsafe_get m.kind i and e = fget m.e i in
  let wi = out.wi and ns = m.ns in
  if kind = Material.k_lambert then begin
    around_into wi ns.mx ns.my ns.mz (Float.sqrt (1. -. v)) (2. *. Float.pi *. w);
    fold wi n true;
    smooth_bumped m tot n wo out
  end
  else if kind = Material.k_phong then begin
    let c = Float.pow v (1. /. (e +. 1.)) in
    reflect_into wi wo ns.mx ns.my ns.mz;
    around_into wi wi.mx wi.my wi.mz c (2. *. Float.pi *. w);
    fold wi n true;
    smooth_bumped m tot n wo out
  end
  else if kind = Material.k_blinn || kind = Material.k_glossy then begin
    let c = Float.pow v (1. /. (e +. 1.)) in
    around_into wi ns.mx ns.my ns.mz c (2. *. Float.pi *. w);
    (* a half vector facing away from wo is not counted by the density:
       dropped (it would reflect wo below the surface without bumps) *)
    dot wo wi > 0.
    && begin
         reflect_into wi wo wi.mx wi.my wi.mz;
         fold wi n true;
         smooth_bumped m tot n wo out
       end
  end
  else if kind = Material.k_mirror then begin
    reflect_into wi wo ns.mx ns.my ns.mz;
    fold wi n true;
    delta_into out (1. /. p) m.c i;
    true
  end
  else begin
    (* glass *)
    let ci = dot wo ns in
    let fr = fresnel e ci in
    if v < fr then begin
      reflect_into wi wo ns.mx ns.my ns.mz;
      fold wi n true;
      delta_into out (1. /. p) m.c2 i
    end
    else begin
      if e = 1. then Vec3.set wi (-.wo.mx) (-.wo.my) (-.wo.mz)
      else begin
        let s2 = e *. e *. (1. -. (ci *. ci)) in
        let ct = Float.sqrt (fmax 0. (1. -. s2)) in
        let k = (e *. ci) -. ct in
        Vec3.set wi ((-.e *. wo.mx) +. (k *. ns.mx)) ((-.e *. wo.my) +. (k *. ns.my)) ((-.e *. wo.mz) +. (k *. ns.mz));
        Vec3.normalize_m wi
      end;
      fold wi n false;
      delta_into out (1. /. p) m.c i
    end;
    true
  end

(* [sample] into [out]; false where it gives [None] *)
let[@inline] sample_into (m : Material.lobes) n wo u v w out =
  if m.bumped then sample_bumped m n wo u v w out else sample_plain m n wo u v w out

(* The vector forms, on a material as a value: the same code, through
   the in-place one *)

let with_vectors ?ns (m : Material.t) (n : Vec3.t) (wo : Vec3.t) (wi : Vec3.t) f =
  let l = Material.lobes () and nm = Vec3.m () and om = Vec3.m () and im = Vec3.m () in
  Material.load l m;
  Option.iter
    (fun ns ->
      Vec3.load l.ns ns;
      l.bumped <- true)
    ns;
  Vec3.load nm n;
  Vec3.load om wo;
  Vec3.load im wi;
  f l nm om im

let eval ?ns m ~n ~wo ~wi =
  with_vectors ?ns m n wo wi (fun l n wo wi ->
      let out = Color.acc 0. in
      eval_into l n wo wi out;
      Color.of_acc out)

let pdf ?ns m ~n ~wo ~wi = with_vectors ?ns m n wo wi pdf_m

let has_smooth (m : Material.t) = Array.exists (fun l -> not (Material.is_delta l)) m.lobes

type sample = { wi : Vec3.t; weight : Color.t; pdf : float; delta : bool }

let sample ?ns (m : Material.t) ~n ~wo u v w =
  with_vectors ?ns m n wo Vec3.zero (fun l n wo _ ->
      let out = sampled () in
      if sample_into l n wo u v w out then
        Some { wi = Vec3.of_m out.wi; weight = Color.of_acc out.weight; pdf = out.p.pdf; delta = out.delta }
      else None)
