// tiles { texture { A } tile2 texture { B } }: POV-Ray's old checker of two textures
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1
  texture { tiles {
      texture { pigment { gradient x color_map { [0 rgb <0.9, 0.3, 0.2>] [1 rgb <1, 0.9, 0.5>] } } finish { diffuse 0.8 } }
      tile2
      texture { pigment { rgb <0.2, 0.3, 0.5> } finish { diffuse 0.6 specular 0.5 roughness 0.02 } } }
    scale 0.8 rotate y*20 } }
sphere { <0, 0.2, 0>, 1.2
  texture { tiles { texture { pigment { rgb 1 } } tile2 texture { pigment { rgb <0.1, 0.6, 0.2> } } } scale 0.5 } }
