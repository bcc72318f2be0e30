// magnet patterns: formulas 1 and 2, mandel and julia kinds, shading types
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -7> look_at <0, 0, 0> angle 60 }
light_source { <-5, 8, -10>, rgb 1 }
#declare Tile = box { <-2, -2, 0>, <2, 2, 0.1> scale 0.7 }
object { Tile pigment { magnet 1 mandel 40 translate x*-1.2 scale 0.5
  color_map { [0 rgb <0,0,0.3>] [0.3 rgb <0,0.8,1>] [1 rgb 1] } } finish { ambient 1 diffuse 0 }
  translate <-1.6, 1.45, 0> }
object { Tile pigment { magnet 2 mandel 40 interior 1, 1 translate x*-1 scale 0.45
  color_map { [0 rgb 0] [0.5 rgb <1,0.5,0>] [1 rgb <1,1,0.5>] } } finish { ambient 1 diffuse 0 }
  translate <1.6, 1.45, 0> }
object { Tile pigment { magnet 1 julia <0.5, 0.3>, 30 exterior 2, 0.5 scale 0.6
  color_map { [0 rgb <0.2,0,0.2>] [1 rgb <1,0.6,1>] } } finish { ambient 1 diffuse 0 }
  translate <-1.6, -1.45, 0> }
object { Tile pigment { magnet 2 julia <0.2, 0.4>, 30 scale 0.6 } finish { ambient 1 diffuse 0 }
  translate <1.6, -1.45, 0> }
