// bicubic_patch: two Bezier patches (type 0 and type 1)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -8> look_at <0, 0.5, 0> angle 45 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 4, -6> color rgb 0.4 }
background { rgb <0.15, 0.15, 0.2> }
plane { y, -1 pigment { checker rgb 0.8, rgb 0.4 } }
bicubic_patch { type 1 flatness 0.01 u_steps 4 v_steps 4
  <0, 0, 2>, <1, 0, 0>, <2, 0, 0>, <3, 0, -2>,
  <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1, 0>,
  <0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2, 0>,
  <0, 3, 2>, <1, 3, 0>, <2, 3, 0>, <3, 3, -2>
  pigment { rgb <0.9, 0.3, 0.2> } finish { specular 0.6 roughness 0.02 }
  rotate x*90 translate <-3.5, -0.5, -1> }
bicubic_patch { type 0 u_steps 3 v_steps 3
  <0, 0, 0>, <1, 1, 0>, <2, 1, 0>, <3, 0, 0>,
  <0, 1, 1>, <1, 2.5, 1>, <2, 2.5, 1>, <3, 1, 1>,
  <0, 1, 2>, <1, 2.5, 2>, <2, 2.5, 2>, <3, 1, 2>,
  <0, 0, 3>, <1, 1, 3>, <2, 1, 3>, <3, 0, 3>
  pigment { gradient y color_map { [0 rgb <0.2, 0.4, 0.9>] [1 rgb <0.9, 0.9, 0.3>] } scale 2 }
  finish { phong 0.5 }
  translate <0.5, -1, -1> }
