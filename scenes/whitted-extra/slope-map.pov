// slope_map: the pattern's value taken to heights and slopes
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0, 0> angle 45 }
light_source { <-4, 10, -5> color rgb 1 }
background { rgb 0.05 }
plane { y, -1 pigment { rgb 0.7 }
  normal { gradient x 0.8 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } scale 0.7 } }
sphere { <-1.3, 0, 0>, 1 pigment { rgb <0.9, 0.5, 0.3> }
  normal { onion 0.5 slope_map { [0 <0, 0>] [0.3 <1, 2>] [0.6 <0.5, -1>] [1 <0, 0>] } scale 0.3 } }
sphere { <1.3, 0, 0>, 1 pigment { rgb <0.3, 0.5, 0.9> }
  normal { leopard 1 slope_map { [0, <1, 0>] [0.2, <0, 0>] [1, <0, 0>] } scale 0.15 } }
