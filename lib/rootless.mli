(** Ruling out a root of a polynomial of degree 2 to 4 on an interval,
    more cheaply than by finding its critical points: {!Poly}'s search
    asks first (most rays miss most surfaces), and the answer is the one
    the search would give. *)

val proved : int -> float -> float -> float -> float -> float -> float -> float -> bool
(** [proved n c4 c3 c2 c1 c0 lo hi]: whether [c4 t^4 + c3 t^3 + c2 t^2 +
    c1 t + c0], of degree [n] (2 to 4: its leading coefficient nonzero,
    those above it zero), keeps one sign on [[lo, hi]] by more than 1e-10
    of the sum of its terms' magnitudes, which is far more than their
    rounding: evaluated in floating point anywhere there, by Horner's
    rule, it is neither zero nor of the other sign. [false] when it
    cannot tell (a root, or a least value close to zero: a ray grazing a
    surface). Past Fujiwara's bound on the roots the leading term
    outweighs the others; within it the second derivative's roots cut the
    interval into convex and concave pieces, bounded below by their ends
    or by their ends' tangents. Allocates nothing (inlined). *)
