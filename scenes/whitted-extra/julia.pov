// julia: the built-in colour map, an exponent, interior/exterior shading types
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -7> look_at <0, 0, 0> angle 60 }
light_source { <-5, 8, -10>, rgb 1 }
#declare Tile = box { <-2, -2, 0>, <2, 2, 0.1> scale 0.7 }
object { Tile pigment { julia <0.353, 0.288>, 30 scale 0.7 } finish { ambient 1 diffuse 0 }
  translate <-1.6, 1.45, 0> }
object { Tile
  pigment { julia <-0.4, 0.6>, 50 interior 1, 1 scale 0.7 color_map { [0 rgb <0,0,0.2>] [0.3 rgb <0,0.7,1>] [1 rgb 1] } }
  finish { ambient 1 diffuse 0 } translate <1.6, 1.45, 0> }
object { Tile
  pigment { julia <0.2, 0.5>, 20 exponent 3 interior 6, 0.3 exterior 6, 0.2 scale 0.7
            color_map { [0 rgb 0] [0.3 rgb <0,1,0>] [0.6 rgb <0.5,1,0>] [1 rgb <1,1,0>] } }
  finish { ambient 1 diffuse 0 } translate <-1.6, -1.45, 0> }
sphere { 0, 1.35
  pigment { julia <0.285, 0.01>, 40 exterior 2, 0.5 scale 0.9
            color_map { [0 rgb <0.4,0.2,0.1>] [0.5 rgb <1,0.8,0.4>] [1 rgb 1] } }
  finish { phong 0.5 } translate <1.6, -1.45, 0> }
