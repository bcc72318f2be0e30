type t = { pattern : Pattern.t; amount : float; xform : Transform.t }

let make kind amount = { pattern = Pattern.make kind; amount; xform = Transform.identity }
let transform t nm = { nm with xform = Transform.then_ nm.xform t }
let h = 1e-3

let perturb nm point n =
  let q = Transform.inv_point nm.xform point in
  let f dx dy dz = Pattern.value nm.pattern (Vec3.add q (Vec3.make dx dy dz)) in
  let g =
    Vec3.make
      ((f h 0. 0. -. f (-.h) 0. 0.) /. (2. *. h))
      ((f 0. h 0. -. f 0. (-.h) 0.) /. (2. *. h))
      ((f 0. 0. h -. f 0. 0. (-.h)) /. (2. *. h))
  in
  (* pattern-space gradient to world space: inverse transpose of the inverse *)
  let g = Transform.normal nm.xform g in
  (* keep only the tangential part; bumps of unit amount tilt by about 45 degrees *)
  let g = Vec3.madd g (-.Vec3.dot g n) n in
  (* fractal patterns have steep gradients (every octave adds about the
     same slope): scaled down to look like POV-Ray's bumps of that amount *)
  let gain =
    match nm.pattern.kind with
    | Pattern.Wrinkles | Pattern.Granite -> 0.15
    | Pattern.Dents -> 0.3
    | _ -> 1.
  in
  let scale = nm.amount *. 0.5 *. gain in
  let m = Vec3.madd n (-.scale) g in
  if Vec3.length2 m = 0. then n else Vec3.normalize m
