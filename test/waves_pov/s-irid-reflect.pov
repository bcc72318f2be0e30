#version 3.7;
global_settings { assumed_gamma 1 } background { rgb <0.3, 0.5, 0.7> }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 8*x up 6*y }
light_source { <-30, 20, -100>, rgb 1 parallel point_at <0, 0, 0> }
plane { z, 0 pigment { rgb 0.2 } finish { ambient 0 diffuse 0.5 reflection 0.6 irid { 0.5 thickness 0.6 turbulence 0.8 } } }
