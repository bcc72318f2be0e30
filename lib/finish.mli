(** POV-Ray's [finish]: how a surface reflects light in the classic model.
    Field defaults are POV-Ray 3.7's (pov-facts.md 5.2). *)

type reflection = {
  rmin : Color.t;  (** reflection at normal incidence ([min]) *)
  rmax : Color.t;  (** reflection at grazing incidence ([max]) *)
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

val default : t
val no_reflection : reflection
val has_reflection : t -> bool
