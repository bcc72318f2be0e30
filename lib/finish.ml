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
  }

let has_reflection f =
  (not (Color.is_black f.reflection.rmin)) || not (Color.is_black f.reflection.rmax)
