// Prisms: linear, quadratic, cubic and Bezier splines, linear and conic
// sweeps, a sub-curve as a hole, an open one.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6, -9> look_at <0, 0.3, 0> angle 48 }
light_source { <-6, 10, -8> rgb 1 }
light_source { <7, 5, -3> rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.85 rgb 0.55 } }
#declare Arrow = array[11] { <0.2,-1>, <0.2,0.2>, <1,-0.2>, <1,0.2>, <0.2,1>, <-0.2,1>, <-1,0.2>, <-1,-0.2>, <-0.2,0.2>, <-0.2,-1>, <0.2,-1> }
prism { linear_spline linear_sweep 0, 0.6, 10,
  <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1>, <-0.5,-0.5>, <0.5,-0.5>, <0.5,0.5>, <-0.5,0.5>, <-0.5,-0.5>
  pigment { rgb <0.9, 0.3, 0.2> } translate <-3, 0, 1> }
prism { quadratic_spline linear_sweep 0, 0.8, 12,
  Arrow[0], Arrow[1], Arrow[2], Arrow[3], Arrow[4], Arrow[5], Arrow[6], Arrow[7], Arrow[8], Arrow[9], Arrow[10], <0.2, 0.2>
  pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.5 } translate <-0.8, 0, 1.2> }
prism { cubic_spline conic_sweep 1, 0.3, 13,
  <-0.2,-1>, Arrow[0], Arrow[1], Arrow[2], Arrow[3], Arrow[4], Arrow[5], Arrow[6], Arrow[7], Arrow[8], Arrow[9], Arrow[10], <0.2, 0.2>
  pigment { rgb <0.3, 0.4, 0.9> } scale <1.5, 1.5, 1.5> rotate 180*x translate <1.6, 1.5, 0.8> }
prism { bezier_spline linear_sweep 0, 1, 8,
  <0, 0>, <0.5, -0.6>, <1, 0>, <1, 0>, <1, 0>, <0.6, 0.8>, <0, 0>, <0, 0> open
  pigment { rgb <0.9, 0.8, 0.2> } translate <2.6, 0, -1.2> }
