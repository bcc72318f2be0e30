(** The chi-square distribution, for POV-Ray's confidence tests (focal
    blur stops sampling a pixel when the variance of its mean falls under
    a threshold built from chi-square quantiles). *)

val upper_tail : df:float -> float -> float
(** [upper_tail ~df x]: the probability that a chi-square variable with
    [df] degrees of freedom ([df > 0]) exceeds [x] (1 for [x <= 0]). *)

val quantile_upper : df:float -> float -> float
(** [quantile_upper ~df p]: the [x] with [upper_tail ~df x = p], for [p]
    in (0, 1) (Cephes' [chdtri], which POV-Ray uses); 0 for [p >= 1],
    infinity for [p <= 0]. Accurate to about 1e-12 relative. *)
