type t = { mutable t : float; mutable u : float; mutable v : float; mutable id : float; mutable floor : float }

let create tmax = { t = tmax; u = 0.; v = 0.; id = 0.; floor = neg_infinity }

let copy_into s d =
  d.t <- s.t;
  d.u <- s.u;
  d.v <- s.v;
  d.id <- s.id

let[@inline] keep h tmin t id u =
  t > tmin && t < h.t
  && (h.t <- t;
      h.id <- id;
      h.u <- u;
      true)
