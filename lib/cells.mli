(** POV-Ray 3.7's [cells] pattern: one value in [[0, 1)] per unit cube,
    the same as POV-Ray's (its 4096-entry permutation, shuffled by its
    linear congruential generator seeded 0, picks one of the first 4096
    outputs of a Mersenne Twister (MT19937, default seed 5489) scaled by
    2^-32). Measured: 39 cells printed by POV-Ray 3.7 agree to the six
    digits printed (test_pattern). *)

val lcg : int -> int
(** POV-Ray's congruence (the C library's rand): the next 32-bit state,
    [1812433253 s + 12345] mod 2^32. *)

val draw15 : int -> int
(** The 15 bits (16 to 30) a draw from state [s] gives. *)

val perm : int array
(** POV-Ray's hash table: 0 .. 4095 shuffled from the top by {!lcg} from
    seed 0 (its noise's and its cells'). *)

val index : int -> int -> int -> int
(** [index ix iy iz]: the cube's slot in {!values}, in [[0, 4096)]
    (coordinates taken mod 4096, negatives included). *)

val values : Float.Array.t
(** The values by slot (4098 of them: POV-Ray's crackle and facets
    points take the three from a cube's slot on, {!Pattern.feature_point}). *)

val value : float -> float -> float -> float
(** The pattern at a point: the value of the cube [floor (c + 1e-10)]
    (POV-Ray's tolerance, so an integer plane belongs to the cube above
    it). *)
