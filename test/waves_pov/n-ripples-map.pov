#version 3.7;
global_settings { assumed_gamma 1  }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 8*x up 6*y }
light_source { <-100, 0, -100>, rgb <1, 0, 0> parallel point_at <0, 0, 0> }
light_source { <0, -100, -100>, rgb <0, 1, 0> parallel point_at <0, 0, 0> }
light_source { <0, 0, -100>, rgb <0, 0, 1> parallel point_at <0, 0, 0> }
plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } normal { ripples scale 0.6 normal_map { [0 gradient x, 1 scale 0.3] [1 gradient y, -1 scale 0.4] } } }
