(** POV-Ray 3.7's noise: its Noise (three generators), DNoise, Turbulence
    and DTurbulence, with its tables rebuilt from how they were made (see
    noise.ml); values checked against POV-Ray's own (test_noise).
    Deterministic and thread-safe. The functions taking coordinates are
    inlined where they are called: a call would box their floats. *)

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
