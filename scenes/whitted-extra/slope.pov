// the slope pattern: the surface's angle to a direction, and altitude
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
plane { y, -1 pigment { rgb 0.6 } }
sphere { <-2, 0.3, 0>, 1.2
  pigment { slope y color_map { [0 rgb <0.2, 0.2, 0.6>] [0.5 rgb <0.9, 0.9, 0.9>] [1 rgb <0.2, 0.7, 0.2>] } } }
torus { 1, 0.4 rotate x*30 translate <1.2, 0.4, 0>
  pigment { slope { y*2, 0.3, 0.9 altitude y, -0.2, 1.2 }
            color_map { [0 rgb <0.6, 0.3, 0.1>] [0.6 rgb <0.5, 0.5, 0.5>] [0.8 rgb 1] } } }
box { <-0.6, -1, -2.2>, <0.6, 0.2, -1.2> rotate y*30
  pigment { slope { -z, 0.2, 0.8 altitude y, -1, 1 } color_map { [0 rgb <1, 0.8, 0>] [1 rgb <0.3, 0, 0.6>] } scale 2 rotate x*20 } }
