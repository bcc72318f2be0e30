(** POV-Ray 3.7's classic lighting model (pov-facts.md section 5):
    ambient, diffuse with brilliance, Phong and Blinn highlights, metallic,
    shadows through filtering and transmitting surfaces, reflection and
    refraction, trace level and ADC bailout. *)

val trace : Scene.t -> Ray.t -> Color.t
(** Radiance (linear working space) along a camera ray (trace level 1). *)

val pixel : Scene.t -> width:int -> height:int -> int -> int -> Color.t
(** The colour of pixel [(x, y)]: one ray through the pixel centre. *)
