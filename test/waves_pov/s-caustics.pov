#version 3.7;
global_settings { assumed_gamma 1  }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 8*x up 6*y }
light_source { <-30, 20, -100>, rgb 1 parallel point_at <0, 0, 0> }
plane { z, 0 pigment { rgb 0.3 } finish { ambient 0 diffuse 1 } } plane { -z, 2 hollow pigment { rgbf <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0 } interior { caustics 1.2 } normal { bumps 0.6 scale 0.5 } }
