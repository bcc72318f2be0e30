type t = { pattern : Pattern.t; amount : float; xform : Transform.t }

let make kind amount = { pattern = Pattern.make kind; amount; xform = Transform.identity }
let transform t nm = { nm with xform = Transform.then_ nm.xform t }

(* Bump strength per unit of amount and of pattern-space slope, calibrated
   on POV-Ray renders of smooth exact patterns (leopard). *)
let strength = 2. /. 15.

(* The slope of the pattern is estimated as POV-Ray does (measured with
   povray 3.7 on normal { gradient x }: the dark bands at each jump of the
   pattern are 0.02 wide ahead and 0.01 behind, and their shading matches
   to 5 digits): the pattern sampled at the four corners of a regular
   tetrahedron of radius [delta] around the point, one corner on +y;
   g = 3/(4 delta) sum v_i f(q + delta v_i), exact for a linear pattern. *)
let delta = 0.02
let tetra =
  let a = 2. *. Float.sqrt 2. /. 3. and b = Float.sqrt 2. /. 3. and c = Float.sqrt (2. /. 3.) in
  [| Vec3.make a (-1. /. 3.) 0.; Vec3.make (-.b) (-1. /. 3.) c; Vec3.make (-.b) (-1. /. 3.) (-.c);
     Vec3.make 0. 1. 0. |]

let perturb nm point n =
  let q = Transform.inv_point nm.xform point in
  let g =
    Array.fold_left
      (fun acc v -> Vec3.madd acc (Pattern.value nm.pattern (Vec3.madd q delta v)) v)
      Vec3.zero tetra
  in
  let g = Vec3.scale (3. /. (4. *. delta)) g in
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
