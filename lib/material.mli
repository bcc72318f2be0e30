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

(** {1 In place}

    The path tracer's form: a vertex's lobes written into flat arrays it
    owns, filled without allocating. *)

val k_lambert : int
val k_mirror : int
val k_phong : int
val k_blinn : int
val k_glossy : int
val k_glass : int

type lobes = {
  mutable count : int;
  kind : int array;  (** [k_lambert] ... [k_glass] *)
  w : Float.Array.t;  (** {!weight} *)
  c : Float.Array.t;
      (** 3 per lobe: Lambert's albedo, Mirror's colour, Phong's and
          Blinn's [k], Glossy's [color], Glass's [transmit] *)
  c2 : Float.Array.t;  (** 3 per lobe: Glass's [reflect] *)
  e : Float.Array.t;  (** the exponent, or Glass's [eta] *)
  em : Color.acc;  (** the emission *)
  pig : Pigment.out;  (** the pigment at the point, as [into] read it *)
  mutable bumped : bool;
      (** the layer has a [normal]: the lobes are seen about the shading
          normal [ns] instead of the surface's (see {!Bsdf}) *)
  ns : Vec3.m;  (** the unit shading normal, when [bumped] *)
  mw : Vec3.m;  (** scratch for {!Bsdf}: a direction mirrored about the surface *)
}

val lobes : unit -> lobes
(** Room for the at most five lobes of a material. *)

val into : lobes -> Texture.t -> Interior.t -> Vec3.m -> Vec3.m -> Vec3.m -> entering:bool -> unit
(** [into m tex inter p n wo ~entering]: {!of_texture} at [p] with [cos_o]
    the dot product of [n] and [wo], written into [m] (the same values);
    [n] is the surface's unit normal on the side of [wo]. Where the layer
    the lobes come from (the top one, of the texture_map entry picked)
    has a [normal], [m.ns] is [n] perturbed by it ({!Normal.perturb_m})
    and then {!face}d, [cos_o] is taken with it and [m.bumped] is set;
    else [m.bumped] is [false] and [m.ns] is not touched. Patterns read
    the uv and surface normal set before ({!Pattern.set_uv},
    {!Pattern.set_normal}). *)

val face_min : float
(** 0.01: the least cosine {!face} leaves. *)

val face : Vec3.m -> Vec3.m -> Vec3.m -> unit
(** [face ns n wo]: the unit shading normal [ns] made to face both the
    viewer and the side of the surface it is on, in place: [n] is the
    surface's unit normal and [wo] the unit direction to the viewer, with
    [n.wo >= 0]. Afterwards [ns] is a unit vector with [ns.n >= face_min]
    and [ns.wo >= face_min]: unchanged where it already was, else moved
    toward the half vector of [n] and [wo] just far enough. *)

val load : lobes -> t -> unit
(** A material's lobes, in order, into [m] (not bumped). *)

val of_lobes : lobes -> t
