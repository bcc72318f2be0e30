type t = { r : float; g : float; b : float }

let make r g b = { r; g; b }
let gray v = { r = v; g = v; b = v }
let black = gray 0.
let white = gray 1.
let[@inline] add a b = { r = a.r +. b.r; g = a.g +. b.g; b = a.b +. b.b }
let[@inline] mul a b = { r = a.r *. b.r; g = a.g *. b.g; b = a.b *. b.b }
let[@inline] scale k a = { r = k *. a.r; g = k *. a.g; b = k *. a.b }

let[@inline] madd a k b =
  { r = a.r +. (k *. b.r); g = a.g +. (k *. b.g); b = a.b +. (k *. b.b) }

let max_channel a = Floats.fmax a.r (Floats.fmax a.g a.b)
(* POV-Ray's grey value *)
let[@inline] grey r g b = (0.297 *. r) +. (0.589 *. g) +. (0.114 *. b)
let luminance a = grey a.r a.g a.b
let is_black a = a.r = 0. && a.g = 0. && a.b = 0.
let pow a e = { r = Float.pow a.r e; g = Float.pow a.g e; b = Float.pow a.b e }
let to_string a = Printf.sprintf "rgb <%g, %g, %g>" a.r a.g a.b

(* A sum being built up in place: mutable and flat, so an update allocates
   nothing (the shading loops keep their running colours in these). *)
type acc = { mutable ar : float; mutable ag : float; mutable ab : float }

let acc v = { ar = v; ag = v; ab = v }
let[@inline] acc_set (a : acc) r g b = a.ar <- r; a.ag <- g; a.ab <- b

let[@inline] acc_store fa i (a : acc) =
  Float.Array.set fa (3 * i) a.ar;
  Float.Array.set fa ((3 * i) + 1) a.ag;
  Float.Array.set fa ((3 * i) + 2) a.ab

let[@inline] acc_load fa i (a : acc) =
  acc_set a (Float.Array.get fa (3 * i)) (Float.Array.get fa ((3 * i) + 1)) (Float.Array.get fa ((3 * i) + 2))
let of_acc (a : acc) = { r = a.ar; g = a.ag; b = a.ab }
let acc_max (a : acc) = Floats.fmax a.ar (Floats.fmax a.ag a.ab)
let acc_is_black (a : acc) = a.ar = 0. && a.ag = 0. && a.ab = 0.
let acc_luminance (a : acc) = grey a.ar a.ag a.ab

type rgbft = { c : t; filter : float; transmit : float }

let opaque c = { c; filter = 0.; transmit = 0. }
let rgbft r g b f t = { c = { r; g; b }; filter = f; transmit = t }
