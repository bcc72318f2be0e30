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
