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

type scratch
(** Room for {!first_root}'s work (one per domain). *)

val scratch : int -> scratch
(** [scratch max_degree]. *)

val first_root : scratch -> Float.Array.t -> int -> float -> bool
(** [first_root sc c degree lo]: whether [c.(0) + c.(1) t + ... +
    c.(degree) t^degree] has a real root above [lo]; the smallest is then
    [root sc].
    Only roots below [1e7] (POV-Ray's largest intersection distance) are
    looked for; a leading term that stays below the rounding of the others
    up to there is dropped (a direction component zero but for rounding
    leaves such terms, with spurious roots far out). Roots are bracketed between the roots of the
    polynomial's derivatives, found the same way (each only when the
    search reaches its bracket), and polished by Newton steps kept in
    their bracket, so no closed formula's cancellation enters. Double
    roots are found where the polynomial reaches zero in floating point.
    For degrees 2 to 4 a polynomial that keeps one sign by far more than
    rounding (the ray misses the surface by some way) is ruled out first,
    more cheaply, with the same answer. Allocates nothing. *)

val first_root_in : scratch -> Float.Array.t -> int -> float -> float -> bool
(** {!first_root} of the roots below a bound too: in [(lo, hi)]. *)

val first_root_below : scratch -> Float.Array.t -> int -> float -> float -> bool
(** [first_root_below sc c degree lo stop]: {!first_root}, the same root
    to the bit, but only looked for below [stop]: [false] where the first
    root is at or past it (its pieces past [stop] are not searched, and
    a polynomial that keeps one sign up to [stop] is ruled out as
    {!first_root} rules one out up to its bound). A query's nearest
    crossing so far is the stop; the root does not move with it. *)

val root : scratch -> float
(** The root {!first_root} found. *)

val cubic_roots_in : Float.Array.t -> float -> float -> float -> float -> float -> float -> int
(** [cubic_roots_in found c3 c2 c1 c0 lo hi]: the roots of [c3 t^3 + c2
    t^2 + c1 t + c0] in [[lo, hi)], in increasing order, into [found]
    (room for 3); their number. The roots {!first_root_in} finds from
    [lo - 1e-12], called again past each root (1e-12 relative past it),
    found in one pass: leading terms dropped as there, and a quadratic's
    or a line's roots the same to the bit; a cubic's critical points
    come from the quadratic formula, not from a search, so its roots
    may differ from those in the last bits. *)
