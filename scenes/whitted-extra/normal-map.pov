// normal_map, average and block lists of normals: the entries' perturbed
// normals weighted, summed and normalised (POV-Ray 3.7's rule)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at 0 angle 50 }
light_source { <-5, 6, -8> color rgb 1 }
#declare Tile = box { <-1.2, -1.2, 0>, <1.2, 1.2, 0.1> }
#declare Rings = normal { onion normal_map { [0 leopard 0.8 scale 0.15] [1 gradient y, 1 scale 5] } scale 3 }
// the two entries around gradient's value, blended
object { Tile pigment { rgb 0.8 }
  normal { gradient x normal_map { [0 leopard 1 scale 0.2] [1 marble 0.7 scale 0.5 rotate 30*z] } scale 2 translate -x }
  translate <-1.3, 1.3, 0> }
// a weighted average
object { Tile pigment { rgb 0.8 }
  normal { average normal_map { [1 leopard 1 scale 0.25] [2 marble 0.5 scale 0.6] [1 onion 0.6 scale 3] } rotate 10*z }
  translate <1.3, 1.3, 0> }
// a map in a map (a declared normal as an entry), the outer one stretched
object { Tile pigment { rgb 0.8 }
  normal { marble normal_map { [0.2 Rings] [0.8 leopard 1.5 scale 0.3 rotate 45*z] } scale <1.5, 0.7, 1> rotate 20*z }
  translate <-1.3, -1.3, 0> }
// a normal per hexagon cell
object { Tile pigment { rgb 0.8 }
  normal { hexagon normal { leopard 1 scale 0.15 } normal { marble 0.8 scale 0.4 } normal { gradient x, 0.7 scale 4 }
    scale 0.6 rotate -90*x }
  translate <1.3, -1.3, 0> }
