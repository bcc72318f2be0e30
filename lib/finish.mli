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
  double_illuminate : bool;
  irid : float;
      (** POV-Ray's [irid { amount thickness t turbulence u }]: the
          reflected light scaled per channel by 1 + amount cos(2 pi t
          (|cos r| + |cos i|) / wavelength) (0: none) *)
  irid_thickness : float;
  irid_turb : float;
      (** set from the object's [double_illuminate]: lights behind the
          surface light it as from the front (POV-Ray's |cos|) *)
}

val default : t
val no_reflection : reflection
val has_reflection : t -> bool

val metallic_k : float -> float -> float
(** [metallic_k m cos]: how far [metallic m] tints a highlight or a
    reflection toward the pigment at an angle of cosine [cos] to the
    normal (POV-Ray's approximate Fresnel term; 0 when [m] is 0). Inlined
    where it is used (its floats are not boxed). *)

val tint : float -> float -> float -> float
(** [tint m k c]: the factor of a channel whose pigment is [c], [k] from
    {!metallic_k}: [1 + k (c - 1)], or 1 when [m] is 0. *)

val fresnel : float -> float -> float
(** [fresnel n c]: POV-Ray's unpolarised Fresnel reflectance for a
    relative index [n] (transmitted side over incident side) and an
    incident cosine [c] (pov-facts.md 5.5); 1 past the critical angle. *)
