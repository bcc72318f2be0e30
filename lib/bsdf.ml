open Color

let inv_pi = 1. /. Float.pi

(* Duff et al. 2017 *)
let basis (n : Vec3.t) =
  let sign = Float.copy_sign 1. n.z in
  let a = -1. /. (sign +. n.z) in
  let b = n.x *. n.y *. a in
  ( Vec3.make (1. +. (sign *. n.x *. n.x *. a)) (sign *. b) (-.sign *. n.x),
    Vec3.make b (sign +. (n.y *. n.y *. a)) (-.n.y) )

let around n cos_t phi =
  let sin_t = Float.sqrt (Float.max 0. (1. -. (cos_t *. cos_t))) in
  let t, b = basis n in
  Vec3.add
    (Vec3.add (Vec3.scale (sin_t *. Float.cos phi) t) (Vec3.scale (sin_t *. Float.sin phi) b))
    (Vec3.scale cos_t n)

let cosine_hemisphere n u1 u2 = around n (Float.sqrt (1. -. u1)) (2. *. Float.pi *. u2)
let reflect wo n = Vec3.madd (Vec3.neg wo) (2. *. Vec3.dot wo n) n

(* density of a direction around [axis] with (e+1)/(2 pi) cos^e *)
let lobe_pdf e c = if c <= 0. then 0. else (e +. 1.) *. 0.5 *. inv_pi *. Float.pow c e

let half wo wi = Vec3.normalize (Vec3.add wo wi)

let fresnel eta ci =
  let ci = Float.min 1. (Float.abs ci) in
  let s2 = eta *. eta *. (1. -. (ci *. ci)) in
  if s2 >= 1. then 1.
  else
    let ct = Float.sqrt (1. -. s2) in
    let rs = ((eta *. ci) -. ct) /. ((eta *. ci) +. ct) in
    let rp = (ci -. (eta *. ct)) /. (ci +. (eta *. ct)) in
    0.5 *. ((rs *. rs) +. (rp *. rp))

(* density of wi through a half-vector lobe *)
let half_pdf e n wo wi =
  let h = half wo wi in
  let oh = Vec3.dot wo h in
  if oh <= 0. then 0. else lobe_pdf e (Vec3.dot n h) /. (4. *. oh)

let lobe_f (l : Material.lobe) n wo wi =
  let ci = Vec3.dot n wi in
  if ci <= 0. then black
  else
    match l with
    | Lambert a -> scale inv_pi a
    | Phong { k; exponent } ->
        let c = Vec3.dot (reflect wo n) wi in
        if c <= 0. then black else scale (Float.pow c exponent *. inv_pi /. ci) k
    | Blinn { k; exponent } ->
        let c = Vec3.dot n (half wo wi) in
        if c <= 0. then black else scale (Float.pow c exponent *. inv_pi /. ci) k
    | Glossy { color; exponent } -> scale (half_pdf exponent n wo wi /. ci) color
    | Mirror _ | Glass _ -> black

let lobe_pdf_of (l : Material.lobe) n wo wi =
  match l with
  | Lambert _ -> Float.max 0. (Vec3.dot n wi) *. inv_pi
  | Phong { exponent; _ } -> lobe_pdf exponent (Vec3.dot (reflect wo n) wi)
  | Blinn { exponent; _ } | Glossy { exponent; _ } -> half_pdf exponent n wo wi
  | Mirror _ | Glass _ -> 0.

let total (m : Material.t) = Array.fold_left (fun s l -> s +. Material.weight l) 0. m.lobes

let eval (m : Material.t) ~n ~wo ~wi =
  Array.fold_left (fun acc l -> add acc (lobe_f l n wo wi)) black m.lobes

let pdf (m : Material.t) ~n ~wo ~wi =
  let w = total m in
  if w <= 0. then 0.
  else
    Array.fold_left
      (fun acc l -> acc +. (Material.weight l /. w *. lobe_pdf_of l n wo wi))
      0. m.lobes

let has_smooth (m : Material.t) = Array.exists (fun l -> not (Material.is_delta l)) m.lobes

type sample = { wi : Vec3.t; weight : Color.t; pdf : float; delta : bool }

let sample (m : Material.t) ~n ~wo u v w =
  let tot = total m in
  if tot <= 0. then None
  else
    (* pick lobe i with probability weight_i / tot *)
    let k = Array.length m.lobes in
    let rec pick i acc =
      let wl = Material.weight m.lobes.(i) in
      if i = k - 1 || u *. tot < acc +. wl then (i, wl) else pick (i + 1) (acc +. wl)
    in
    let i, wl = pick 0 0. in
    let p = wl /. tot in
    let smooth wi =
      let ci = Vec3.dot n wi in
      if ci <= 0. then None
      else
        let pd = pdf m ~n ~wo ~wi in
        if pd <= 0. then None
        else
          let f = eval m ~n ~wo ~wi in
          Some { wi; weight = scale (ci /. pd) f; pdf = pd; delta = false }
    in
    match m.lobes.(i) with
    | Lambert _ -> smooth (cosine_hemisphere n v w)
    | Phong { exponent; _ } ->
        let c = Float.pow v (1. /. (exponent +. 1.)) in
        smooth (around (reflect wo n) c (2. *. Float.pi *. w))
    | Blinn { exponent; _ } | Glossy { exponent; _ } ->
        let c = Float.pow v (1. /. (exponent +. 1.)) in
        let h = around n c (2. *. Float.pi *. w) in
        smooth (reflect wo h)
    | Mirror c ->
        Some { wi = reflect wo n; weight = scale (1. /. p) c; pdf = 0.; delta = true }
    | Glass { eta; reflect = cr; transmit } ->
        let ci = Vec3.dot wo n in
        let fr = fresnel eta ci in
        if v < fr then
          Some { wi = reflect wo n; weight = scale (1. /. p) cr; pdf = 0.; delta = true }
        else
          let s2 = eta *. eta *. (1. -. (ci *. ci)) in
          let ct = Float.sqrt (Float.max 0. (1. -. s2)) in
          (* Heckbert: T = eta D + (eta c - cos_t) n, D = -wo *)
          let wi = Vec3.normalize (Vec3.madd (Vec3.scale (-.eta) wo) ((eta *. ci) -. ct) n) in
          Some { wi; weight = scale (1. /. p) transmit; pdf = 0.; delta = true }
