(** Solid noise for patterns: camlray's own gradient noise (Perlin's
    "improved noise" construction: quintic fade, 12 edge gradients) with a
    permutation table made by a fixed shuffle. It is NOT POV-Ray's noise
    (whose tables are not reproduced), so noise-based patterns (bozo,
    granite, marble with turbulence, ...) look alike but differ pixel by
    pixel from POV-Ray's. Deterministic and thread-safe. The functions
    taking coordinates are inlined where they are called: a call would box
    their floats. *)

val snoise : Vec3.t -> float
(** Signed noise, about [[-1, 1]], 0 at lattice points. *)

val snoise3 : float -> float -> float -> float
(** {!snoise} at [(x, y, z)]. *)

val noise3 : float -> float -> float -> float
(** Scalar noise in [[0, 1]], 0.5 at lattice points. *)

val dnoise3 : float -> float -> float -> Vec3.m -> unit
(** [dnoise3 x y z out]: camlray's vector noise (POV-Ray's [DNoise], with
    camlray's own noise): three decorrelated signed noises at the point,
    each about [[-1, 1]], into [out]; one octave of {!turbulence_m}. *)

val turbulence_m : octaves:int -> omega:float -> lambda:float -> Vec3.m -> Vec3.m -> unit
(** [turbulence_m ~octaves ~omega ~lambda p out]: [sum_{i < octaves}
    omega^i dnoise(lambda^i p)] into [out], where [dnoise] is three
    decorrelated signed noises: the displacement POV-Ray's [turbulence]
    warp scales per axis. *)

val fractal3 : int -> float -> float -> float -> float
(** [fractal3 octaves x y z]: [sum_i |snoise(2^i p)| / 2^i], in about
    [[0, 2]]: the scalar 1/f noise used by granite, wrinkles, agate. *)

(** {1 POV-Ray 3.7's noise}

    Its tables rebuilt from how they were made (see noise.ml); values
    checked against POV-Ray's [f_noise3d]. *)

type generator = int
(** POV-Ray's [noise_generator]: 1 the original noise, 2 the same with its
    range stretched to about [[0, 1]] (POV-Ray 3.7's default), 3 Perlin's
    solid noise. *)

val noise : generator -> float -> float -> float -> float
(** POV-Ray's [Noise]: in [[0, 1]]. *)

val dnoise : float -> float -> float -> Vec3.m -> unit
(** POV-Ray's [DNoise] (the same for every generator) into the vector. *)

val turbulence : generator -> octaves:int -> omega:float -> lambda:float -> float -> float -> float -> float
(** POV-Ray's [Turbulence]. *)

val dturbulence : octaves:int -> omega:float -> lambda:float -> Vec3.m -> Vec3.m -> unit
(** [dturbulence ~octaves ~omega ~lambda p out]: POV-Ray's [DTurbulence]. *)

(**/**)

val r_table : Float.Array.t
val hash_table : int array
