// Patterned textures: texture_map and a checker of textures.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.7, 0> }
light_source { <-4, 6, -5>, rgb 1 }
#declare Shiny = texture { pigment { rgb <0.9, 0.2, 0.2> } finish { phong 0.9 phong_size 60 reflection 0.2 } }
#declare Matte = texture { pigment { rgb <0.2, 0.4, 0.9> } finish { diffuse 0.9 } }
plane { y, 0 texture { checker texture { Matte }, texture { pigment { rgb 0.9 } } scale 0.7 } }
sphere { <-1.3, 1, 0>, 1
  texture { gradient y texture_map { [0.3 Shiny] [0.7 Matte] } scale 0.5 } }
sphere { <1.3, 1, 0>, 1
  texture { radial frequency 8 texture_map { [0.5 pigment { rgbt <1,1,0.6,0.5> }] [0.5 pigment { rgb <0.1, 0.7, 0.2> } finish { specular 0.5 }] } } }
