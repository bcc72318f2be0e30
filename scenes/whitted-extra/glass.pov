#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2, -5> look_at <0, 0.8, 0> }
light_source { <-3, 8, -6>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb <0.2, 0.3, 0.6> } }
sphere { <0, 1, 0>, 1 pigment { rgbf <0.9, 1, 0.9, 0.9> } finish { ambient 0 diffuse 0 specular 1 roughness 0.003 reflection { 0.02, 1 fresnel on } }
  interior { ior 1.5 } }
sphere { <0, 1, 0>, 0.4 pigment { rgbt <1, 0.5, 0.5, 0.8> } interior { ior 1.33 } }
