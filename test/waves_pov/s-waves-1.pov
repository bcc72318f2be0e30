#version 3.7;
global_settings { assumed_gamma 1 number_of_waves 1 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 8*x up 6*y }
light_source { <-30, 20, -100>, rgb 1 parallel point_at <0, 0, 0> }
plane { z, 0 pigment { waves scale 0.3 } finish { ambient 1 diffuse 0 } }
