#version 3.7;
global_settings { assumed_gamma 1  }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 8*x up 6*y }
light_source { <-30, 20, -100>, rgb 1 parallel point_at <0, 0, 0> }
plane { z, 0 pigment { checker rgb 0.15 rgb 0.5 scale 0.5 } finish { ambient 1 diffuse 0 } } box { <-3, -1.2, -1.2>, <3, 1.2, 1.2> rotate x*35 translate -3*z pigment { rgbf 1 } finish { ambient 0 diffuse 0 irid { 0.8 thickness 0.5 turbulence 0.5 } } interior { ior 1.5 } }
