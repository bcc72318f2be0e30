(** Polynomial roots for the quadric-free shapes (the torus): real roots
    isolated between the critical points, then found by safeguarded
    Newton steps inside a sign-changing bracket. This never suffers the
    cancellation of closed-form quartic formulas, so grazing rays give no
    speckles. *)

val cubic_roots : float -> float -> float -> float -> float array
(** [cubic_roots a b c d]: the real roots of [a t^3 + b t^2 + c t + d]
    ([a <> 0]), in increasing order, each polished by Newton's method. *)

val first_quartic_root : float -> float -> float -> float -> float -> float -> float -> float
(** [first_quartic_root a b c d e lo hi]: the smallest root of
    [a t^4 + b t^3 + c t^2 + d t + e] ([a > 0]) in the open interval
    [(lo, hi)], or [infinity]. Roots of even multiplicity (tangency) are
    found only when the polynomial reaches zero or below in floating
    point. *)
