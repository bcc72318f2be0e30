type t = { origin : Vec3.t; dir : Vec3.t }

let make origin dir = { origin; dir }
let[@inline] at r t = Vec3.madd r.origin t r.dir
let epsilon = 1e-6
let shadow_epsilon = 1e-3
