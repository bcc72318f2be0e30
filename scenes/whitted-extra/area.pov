#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> }
light_source { <2, 6, -3>, rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 5, 5 adaptive 1 }
plane { y, 0 pigment { rgb 0.8 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.2, 0.5, 0.9> } finish { specular 0.6 roughness 0.02 } }
