#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -4> look_at <0, 1, 0> }
light_source { <0, 2, 5>, rgb 1 }
light_source { <-3, 4, -5>, rgb 0.3 }

plane { z, 1 pigment { checker rgb <1, 0.8, 0.5>, rgb <0.3,0.6,1> } finish { diffuse 0.5, 0.6 } }
