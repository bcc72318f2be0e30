type t = {
  ior : float;
  fade_distance : float;
  fade_power : float;
  fade_color : Color.t;
}

let default =
  { ior = 1.; fade_distance = 0.; fade_power = 0.; fade_color = Color.black }

let[@inline] fade_channel i c d =
  if i.fade_distance = 0. then 1.
  else if i.fade_power >= 1000. then Float.exp (-.(1. -. c) *. d /. i.fade_distance)
  else c +. ((1. -. c) /. (1. +. Float.pow (d /. i.fade_distance) i.fade_power))
