type t = { origin : Vec3.t; dir : Vec3.t }

let make origin dir = { origin; dir }
let[@inline] at r t = Vec3.madd r.origin t r.dir
let epsilon = 1e-6
let shadow_epsilon = 1e-3

type scratch = {
  mutable ox : float;
  mutable oy : float;
  mutable oz : float;
  mutable dx : float;
  mutable dy : float;
  mutable dz : float;
  mutable far : float;
}

let scratch () = { ox = 0.; oy = 0.; oz = 0.; dx = 0.; dy = 0.; dz = 1.; far = infinity }

let[@inline] load s r =
  s.ox <- r.origin.x;
  s.oy <- r.origin.y;
  s.oz <- r.origin.z;
  s.dx <- r.dir.x;
  s.dy <- r.dir.y;
  s.dz <- r.dir.z;
  s.far <- infinity

let[@inline] set s (o : Vec3.m) dx dy dz =
  s.ox <- o.mx;
  s.oy <- o.my;
  s.oz <- o.mz;
  s.dx <- dx;
  s.dy <- dy;
  s.dz <- dz

let[@inline] copy src dst =
  dst.ox <- src.ox;
  dst.oy <- src.oy;
  dst.oz <- src.oz;
  dst.dx <- src.dx;
  dst.dy <- src.dy;
  dst.dz <- src.dz;
  dst.far <- src.far

let of_ray r =
  let s = scratch () in
  load s r;
  s
