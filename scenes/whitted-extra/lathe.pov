// Lathes: linear, quadratic, cubic and Bezier profiles turned about y.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -8> look_at <0, 0.8, 0> angle 50 }
light_source { <-6, 10, -8> rgb 1 }
light_source { <7, 5, -3> rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.85 rgb 0.55 } }
lathe { linear_spline 6, <0, 0>, <1, 0>, <1, 0.3>, <0.4, 0.6>, <0.7, 1.6>, <0, 1.6>
  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } translate <-3, 0, 0.5> }
lathe { quadratic_spline 7, <0, 0.2>, <0.8, 0>, <0.9, 0.6>, <0.3, 1.2>, <0.6, 1.8>, <0.1, 2.1>, <0, 2.2>
  pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.5 } translate <-1, 0, 0> }
lathe { cubic_spline 8, <0, -0.2>, <0, 0>, <0.9, 0.2>, <0.5, 0.8>, <0.8, 1.4>, <0.2, 1.9>, <0, 2>, <0, 2.2>
  pigment { rgb <0.3, 0.4, 0.9> } finish { specular 0.5 roughness 0.02 } translate <1, 0, 0> }
lathe { bezier_spline 8, <0, 0>, <1.2, 0>, <0.2, 0.8>, <0.6, 1>, <0.6, 1>, <1, 1.2>, <0.6, 1.6>, <0, 1.7>
  pigment { rgb <0.9, 0.8, 0.2> } translate <3, 0, 0.5> }
