// Normal perturbation with a smooth exact pattern (leopard): should match
// POV-Ray closely (scaled, non-uniformly scaled, rotated, on a sphere).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.7, 0> }
light_source { <-4, 6, -5>, rgb 1 }
plane { y, 0 pigment { rgb 0.8 } normal { leopard 0.6 scale 0.1 } finish { phong 0.5 } }
sphere { <-1.5, 1, 0>, 1 pigment { rgb <0.9, 0.5, 0.3> } normal { leopard 1 scale <0.2, 0.1, 0.15> rotate <20, 30, 40> } finish { phong 0.8 phong_size 60 } }
sphere { <1.5, 1, 0>, 1 texture { pigment { rgb <0.3, 0.5, 0.9> } normal { leopard 2 scale 0.3 } finish { specular 0.7 roughness 0.01 } } translate z*0.5 }
