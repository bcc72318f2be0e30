type t = { x : float; y : float; z : float }

let make x y z = { x; y; z }
let zero = { x = 0.; y = 0.; z = 0. }
let one = { x = 1.; y = 1.; z = 1. }
let unit_x = { x = 1.; y = 0.; z = 0. }
let unit_y = { x = 0.; y = 1.; z = 0. }
let unit_z = { x = 0.; y = 0.; z = 1. }
let[@inline] add a b = { x = a.x +. b.x; y = a.y +. b.y; z = a.z +. b.z }
let[@inline] sub a b = { x = a.x -. b.x; y = a.y -. b.y; z = a.z -. b.z }
let[@inline] neg a = { x = -.a.x; y = -.a.y; z = -.a.z }
let[@inline] mul a b = { x = a.x *. b.x; y = a.y *. b.y; z = a.z *. b.z }
let[@inline] div a b = { x = a.x /. b.x; y = a.y /. b.y; z = a.z /. b.z }
let[@inline] scale k a = { x = k *. a.x; y = k *. a.y; z = k *. a.z }

let[@inline] madd a k b =
  { x = a.x +. (k *. b.x); y = a.y +. (k *. b.y); z = a.z +. (k *. b.z) }

let[@inline] dot a b = (a.x *. b.x) +. (a.y *. b.y) +. (a.z *. b.z)

let[@inline] cross a b =
  {
    x = (a.y *. b.z) -. (a.z *. b.y);
    y = (a.z *. b.x) -. (a.x *. b.z);
    z = (a.x *. b.y) -. (a.y *. b.x);
  }

let[@inline] length2 a = dot a a
let[@inline] length a = Float.sqrt (dot a a)

let normalize a =
  let l = length a in
  if l > 0. then scale (1. /. l) a else a

let dist a b = length (sub a b)
let min a b = { x = Float.min a.x b.x; y = Float.min a.y b.y; z = Float.min a.z b.z }
let max a b = { x = Float.max a.x b.x; y = Float.max a.y b.y; z = Float.max a.z b.z }

let get v = function
  | 0 -> v.x
  | 1 -> v.y
  | 2 -> v.z
  | i -> invalid_arg (Printf.sprintf "Vec3.get %d" i)

let lerp a b s = madd a s (sub b a)
let is_finite v = Float.is_finite v.x && Float.is_finite v.y && Float.is_finite v.z
let max_component v = Float.max v.x (Float.max v.y v.z)
let to_string v = Printf.sprintf "<%g, %g, %g>" v.x v.y v.z

type m = { mutable mx : float; mutable my : float; mutable mz : float }

let m () = { mx = 0.; my = 0.; mz = 0. }
let[@inline] set (v : m) x y z = v.mx <- x; v.my <- y; v.mz <- z
let[@inline] load (v : m) a = v.mx <- a.x; v.my <- a.y; v.mz <- a.z
let[@inline] of_m (v : m) = { x = v.mx; y = v.my; z = v.mz }

let[@inline] dot_m (a : m) (b : m) = (a.mx *. b.mx) +. (a.my *. b.my) +. (a.mz *. b.mz)

let[@inline] inv_len x y z =
  let l = Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) in
  if l > 0. then 1. /. l else 1.

let[@inline] normalize_m (v : m) =
  let x = v.mx and y = v.my and z = v.mz in
  let l = Float.sqrt ((x *. x) +. (y *. y) +. (z *. z)) in
  if l > 0. then
    let k = 1. /. l in
    set v (k *. x) (k *. y) (k *. z)
