#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.5, 0> }
light_source { <0, 10, 0>, rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
sphere { <-1.2, 1.5, 0>, 0.8 pigment { rgbf <1, 0.6, 0.3, 0.9> } interior { fade_distance 0.5 fade_power 2 fade_color <0.2, 0.5, 1> } }
sphere { <1.2, 1.5, 0>, 0.8 pigment { rgbt 0.8 } interior { ior 1.5 fade_distance 1 fade_power 1001 } finish { specular 0.8 roughness 0.01 } }
