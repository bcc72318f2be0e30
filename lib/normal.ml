type t = { pattern : Pattern.t; amount : float; xform : Transform.t }

let make kind amount = { pattern = Pattern.make kind; amount; xform = Transform.identity }
let transform t nm = { nm with xform = Transform.then_ nm.xform t }
let h = 1e-3

(* Bump strength per unit of amount and of pattern-space slope, calibrated
   on POV-Ray renders of smooth exact patterns (leopard). *)
let strength = 2. /. 15.

let perturb nm point n =
  let q = Transform.inv_point nm.xform point in
  let f dx dy dz = Pattern.value nm.pattern (Vec3.add q (Vec3.make dx dy dz)) in
  let g =
    Vec3.make
      ((f h 0. 0. -. f (-.h) 0. 0.) /. (2. *. h))
      ((f 0. h 0. -. f 0. (-.h) 0.) /. (2. *. h))
      ((f 0. 0. h -. f 0. 0. (-.h)) /. (2. *. h))
  in
  (* as POV-Ray: tilt a unit normal in pattern space, then bring it back *)
  let np = Vec3.normalize (Transform.normal (Transform.inverse nm.xform) n) in
  (* POV-Ray computes bumps, dents, ripples, waves and wrinkles with
     formulas of their own, much stronger than the generic slope; these
     gains make camlray's look alike (set by eye: the noise differs) *)
  let gain =
    match nm.pattern.kind with
    | Pattern.Bozo | Pattern.Bumps | Pattern.Spotted | Pattern.Ripples | Pattern.Waves -> 12.
    | Pattern.Dents -> 1.5
    | Pattern.Wrinkles | Pattern.Granite -> 0.6
    | _ -> 1.
  in
  (* the full slope, normal component included *)
  let mp = Vec3.madd np (-.nm.amount *. strength *. gain) g in
  let m = Transform.normal nm.xform mp in
  if Vec3.length2 m = 0. then n else Vec3.normalize m
