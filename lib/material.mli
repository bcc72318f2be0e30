(** Physical materials for the Monte Carlo mode, built from a POV-Ray
    texture at a hit point. A material is a sum of lobes (each lobe
    carries its own weight, so the sum is what POV-Ray adds up); the
    mapping is documented in docs/mc-materials.md. *)

(** One scattering lobe. Directions are unit vectors; [n] is the shading
    normal facing the outgoing direction [wo]. *)
type lobe =
  | Lambert of Color.t  (** f = albedo / pi *)
  | Mirror of Color.t  (** perfect specular reflection of this colour (a delta lobe) *)
  | Phong of { k : Color.t; exponent : float }
      (** f = k (r.wi)^e / (pi cos theta_i), r the mirror direction of wo:
          a point light of POV colour c gives POV's phong term k c (r.l)^e *)
  | Blinn of { k : Color.t; exponent : float }
      (** f = k (n.h)^e / (pi cos theta_i): POV's [specular] term *)
  | Glossy of { color : Color.t; exponent : float }
      (** a blurred metal reflection: half vectors distributed as
          (e+1)/(2 pi) (n.h)^e, and f chosen so that each sampled
          direction above the surface carries exactly [color] *)
  | Glass of { eta : float; reflect : Color.t; transmit : Color.t }
      (** smooth dielectric (delta): exact unpolarised Fresnel
          reflectance F for the relative index [eta] = n_incident /
          n_transmitted, total internal reflection; reflects F x [reflect],
          transmits (1 - F) x [transmit]. *)

type t = { lobes : lobe array; emission : Color.t }
(** [emission]: radiance emitted from both sides of the surface. *)

val black : t
(** No lobes, no emission: absorbs everything. *)

val of_texture : Texture.t -> Interior.t -> Vec3.t -> cos_o:float -> entering:bool -> t
(** The material at a world point. [cos_o] = cosine between the viewer
    direction and the normal (for POV's angle-dependent reflection);
    [entering]: the ray arrives from outside the object (for the relative
    index of refraction: outside is assumed to be air, ior 1). Only the
    top texture layer is used. *)

val is_delta : lobe -> bool

val weight : lobe -> float
(** A rough albedo, used to choose lobes in proportion when sampling. *)
