type reflection = {
  rmin : Color.t;
  rmax : Color.t;
  falloff : float;
  fresnel : bool;
  exponent : float;
  rmetallic : float;
}

type t = {
  ambient : Color.t;
  emission : Color.t;
  diffuse : float;
  diffuse_back : float;
  brilliance : float;
  phong : float;
  phong_size : float;
  specular : float;
  roughness : float;
  metallic : float;
  reflection : reflection;
  conserve_energy : bool;
  double_illuminate : bool;
  irid : float;
  irid_thickness : float;
  irid_turb : float;
}

let no_reflection =
  {
    rmin = Color.black;
    rmax = Color.black;
    falloff = 1.;
    fresnel = false;
    exponent = 1.;
    rmetallic = 0.;
  }

let default =
  {
    ambient = Color.gray 0.1;
    emission = Color.black;
    diffuse = 0.6;
    diffuse_back = 0.;
    brilliance = 1.;
    phong = 0.;
    phong_size = 40.;
    specular = 0.;
    roughness = 0.05;
    metallic = 0.;
    reflection = no_reflection;
    conserve_energy = false;
    double_illuminate = false;
    irid = 0.;
    irid_thickness = 0.;
    irid_turb = 0.;
  }

let has_reflection f =
  (not (Color.is_black f.reflection.rmin)) || not (Color.is_black f.reflection.rmax)

(* comparisons as OCaml compiles them, no call: the same as Float.min
   and Float.max for the values here (NaN passes through both) *)
let fmin = Floats.fmin
let fmax = Floats.fmax

(* POV-Ray's approximate metallic Fresnel term, x = angle / 90 degrees:
   [m] > 0, the tint is 1 + k (c - 1) per channel c of the pigment, k as
   follows; [m] = 0, no tint (1) *)
let[@inline] metallic_k m cos_angle =
  let x = Float.acos (fmin 1. (Float.abs cos_angle)) /. (Float.pi /. 2.) in
  let f = (0.014567225 /. ((x -. 1.12) ** 2.)) -. 0.011612903 in
  let f = fmin 1. (fmax 0. f) in
  m *. (1. -. f)

let[@inline] tint m k c = if m = 0. then 1. else 1. +. (k *. (c -. 1.))

(* Unpolarised Fresnel reflectance for a relative index n = n_t / n_i
   (POV-Ray's formula, pov-facts 5.5); 1 past the critical angle. *)
let fresnel n c =
  let g2 = (n *. n) +. (c *. c) -. 1. in
  if g2 <= 0. then 1.
  else
    let g = Float.sqrt g2 in
    let a = (g -. c) /. (g +. c) and b = ((c *. (g +. c)) -. 1.) /. ((c *. (g -. c)) +. 1.) in
    0.5 *. a *. a *. (1. +. (b *. b))
