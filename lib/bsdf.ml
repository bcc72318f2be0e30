open Color

(* if-based min/max: Float.min/max order NaN and -0 through a C call *)
let[@inline] fmax (a : float) b = if a >= b then a else b
let[@inline] fmin (a : float) b = if a <= b then a else b

let inv_pi = 1. /. Float.pi

(* Duff et al. 2017 *)
let basis (n : Vec3.t) =
  let sign = Float.copy_sign 1. n.z in
  let a = -1. /. (sign +. n.z) in
  let b = n.x *. n.y *. a in
  ( Vec3.make (1. +. (sign *. n.x *. n.x *. a)) (sign *. b) (-.sign *. n.x),
    Vec3.make b (sign +. (n.y *. n.y *. a)) (-.n.y) )

(* [around n cos_t phi] is [sin_t cos phi t + sin_t sin phi b + cos_t n]
   with [t, b = basis n], computed in floats (same operations, one
   vector allocated). *)
let around (n : Vec3.t) cos_t phi =
  let sin_t = Float.sqrt (fmax 0. (1. -. (cos_t *. cos_t))) in
  let sign = if n.z > 0. || (n.z = 0. && 1. /. n.z > 0.) then 1. else -1. in
  let a = -1. /. (sign +. n.z) in
  let b = n.x *. n.y *. a in
  let tx = 1. +. (sign *. n.x *. n.x *. a) and ty = sign *. b and tz = -.sign *. n.x in
  let bx = b and by = sign +. (n.y *. n.y *. a) and bz = -.n.y in
  let kt = sin_t *. Float.cos phi and kb = sin_t *. Float.sin phi in
  Vec3.make
    ((kt *. tx) +. (kb *. bx) +. (cos_t *. n.x))
    ((kt *. ty) +. (kb *. by) +. (cos_t *. n.y))
    ((kt *. tz) +. (kb *. bz) +. (cos_t *. n.z))

let cosine_hemisphere n u1 u2 = around n (Float.sqrt (1. -. u1)) (2. *. Float.pi *. u2)
let reflect wo n = Vec3.madd (Vec3.neg wo) (2. *. Vec3.dot wo n) n

(* density of a direction around [axis] with (e+1)/(2 pi) cos^e *)
let lobe_pdf e c = if c <= 0. then 0. else (e +. 1.) *. 0.5 *. inv_pi *. Float.pow c e

let half wo wi = Vec3.normalize (Vec3.add wo wi)

let fresnel eta ci =
  let ci = fmin 1. (Float.abs ci) in
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

(* A lobe's f is a scalar times the lobe's colour: [lobe_k] is the scalar
   (0 for deltas and below the surface), so that sums over lobes need no
   colour per lobe. *)
let lobe_k (l : Material.lobe) n wo wi =
  let ci = Vec3.dot n wi in
  if ci <= 0. then 0.
  else
    match l with
    | Lambert _ -> inv_pi
    | Phong { exponent; _ } ->
        let c = Vec3.dot (reflect wo n) wi in
        if c <= 0. then 0. else Float.pow c exponent *. inv_pi /. ci
    | Blinn { exponent; _ } ->
        let c = Vec3.dot n (half wo wi) in
        if c <= 0. then 0. else Float.pow c exponent *. inv_pi /. ci
    | Glossy { exponent; _ } -> half_pdf exponent n wo wi /. ci
    | Mirror _ | Glass _ -> 0.

let lobe_color (l : Material.lobe) =
  match l with
  | Lambert a | Mirror a -> a
  | Phong { k; _ } | Blinn { k; _ } -> k
  | Glossy { color; _ } -> color
  | Glass { transmit; _ } -> transmit

let lobe_pdf_of (l : Material.lobe) n wo wi =
  match l with
  | Lambert _ -> fmax 0. (Vec3.dot n wi) *. inv_pi
  | Phong { exponent; _ } -> lobe_pdf exponent (Vec3.dot (reflect wo n) wi)
  | Blinn { exponent; _ } | Glossy { exponent; _ } -> half_pdf exponent n wo wi
  | Mirror _ | Glass _ -> 0.

let total (m : Material.t) =
  let s = ref 0. in
  for i = 0 to Array.length m.lobes - 1 do
    s := !s +. Material.weight (Array.unsafe_get m.lobes i)
  done;
  !s

let eval (m : Material.t) ~n ~wo ~wi =
  let r = ref 0. and g = ref 0. and b = ref 0. in
  for i = 0 to Array.length m.lobes - 1 do
    let l = Array.unsafe_get m.lobes i in
    let k = lobe_k l n wo wi in
    if k <> 0. then begin
      let c = lobe_color l in
      r := !r +. (k *. c.r);
      g := !g +. (k *. c.g);
      b := !b +. (k *. c.b)
    end
    else begin
      (* the sum adds black: +0, as before (keeps -0 sums bit-identical) *)
      r := !r +. 0.;
      g := !g +. 0.;
      b := !b +. 0.
    end
  done;
  make !r !g !b

let pdf_total (m : Material.t) w ~n ~wo ~wi =
  if w <= 0. then 0.
  else begin
    let acc = ref 0. in
    for i = 0 to Array.length m.lobes - 1 do
      let l = Array.unsafe_get m.lobes i in
      acc := !acc +. (Material.weight l /. w *. lobe_pdf_of l n wo wi)
    done;
    !acc
  end

let pdf (m : Material.t) ~n ~wo ~wi = pdf_total m (total m) ~n ~wo ~wi

let has_smooth (m : Material.t) =
  let r = ref false in
  for i = 0 to Array.length m.lobes - 1 do
    if not (Material.is_delta (Array.unsafe_get m.lobes i)) then r := true
  done;
  !r

type sample = { wi : Vec3.t; weight : Color.t; pdf : float; delta : bool }

(* the lobe [sample] picks: i with probability weight_i / tot *)
let pick (m : Material.t) tot u =
  let k = Array.length m.lobes in
  let i = ref 0 and acc = ref 0. and go = ref true in
  while !go do
    let wl = Material.weight (Array.unsafe_get m.lobes !i) in
    if !i = k - 1 || u *. tot < !acc +. wl then go := false
    else (
      acc := !acc +. wl;
      incr i)
  done;
  !i

let smooth (m : Material.t) tot ~n ~wo wi =
  let ci = Vec3.dot n wi in
  if ci <= 0. then None
  else
    let pd = pdf_total m tot ~n ~wo ~wi in
    if pd <= 0. then None
    else
      let f = eval m ~n ~wo ~wi in
      Some { wi; weight = scale (ci /. pd) f; pdf = pd; delta = false }

let sample (m : Material.t) ~n ~wo u v w =
  let tot = total m in
  if tot <= 0. then None
  else
    let i = pick m tot u in
    let p = Material.weight m.lobes.(i) /. tot in
    match m.lobes.(i) with
    | Lambert _ -> smooth m tot ~n ~wo (cosine_hemisphere n v w)
    | Phong { exponent; _ } ->
        let c = Float.pow v (1. /. (exponent +. 1.)) in
        smooth m tot ~n ~wo (around (reflect wo n) c (2. *. Float.pi *. w))
    | Blinn { exponent; _ } | Glossy { exponent; _ } ->
        let c = Float.pow v (1. /. (exponent +. 1.)) in
        let h = around n c (2. *. Float.pi *. w) in
        smooth m tot ~n ~wo (reflect wo h)
    | Mirror c ->
        Some { wi = reflect wo n; weight = scale (1. /. p) c; pdf = 0.; delta = true }
    | Glass { eta; reflect = cr; transmit } ->
        let ci = Vec3.dot wo n in
        let fr = fresnel eta ci in
        if v < fr then
          Some { wi = reflect wo n; weight = scale (1. /. p) cr; pdf = 0.; delta = true }
        else
          let s2 = eta *. eta *. (1. -. (ci *. ci)) in
          let ct = Float.sqrt (fmax 0. (1. -. s2)) in
          (* Heckbert: T = eta D + (eta c - cos_t) n, D = -wo *)
          let wi = Vec3.normalize (Vec3.madd (Vec3.scale (-.eta) wo) ((eta *. ci) -. ct) n) in
          Some { wi; weight = scale (1. /. p) transmit; pdf = 0.; delta = true }
