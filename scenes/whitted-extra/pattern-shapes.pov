// boxed, cylindrical and pigment_pattern patterns (pigments, and a normal)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
background { rgb <0.1, 0.1, 0.15> }
plane { y, -1 pigment { cylindrical color_map { [0 rgb <0.2, 0.3, 0.2>] [1 rgb <0.9, 0.8, 0.5>] } scale 4 } }
box { -1, 1 translate <-2.3, 0, 0>
  pigment { boxed color_map { [0 rgb <0.1, 0.1, 0.5>] [0.5 rgb <0.9, 0.3, 0.1>] [1 rgb 1] } scale 1.2 } }
sphere { 0, 1
  pigment { pigment_pattern { gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } scale 0.5 }
            color_map { [0 rgb <0.2, 0.2, 0.2>] [0.3 rgb <0.9, 0.9, 0.2>] } } }
box { -1, 1 translate <2.3, 0, 0>
  pigment { rgb <0.8, 0.8, 0.8> }
  normal { pigment_pattern { onion color_map { [0 rgb 0] [0.5 rgb 1] [1 rgb 0] } scale 0.7 } 0.6 } }
