#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -4> look_at <0, 0.7, 0> }
light_source { <-4, 6, -5>, rgb 1 }
plane { y, 0 pigment { rgb 0.7 } }
sphere { <0, 1, 0>, 1
  texture { pigment { rgb <0.1, 0.6, 0.2> } finish { phong 0.5 } }
  texture { pigment { gradient y color_map { [0 rgbt <1,0,0,0.3>] [0.5 rgbt <1,1,1,1>] [1 rgbf <0,0,1,0.6>] } scale 0.4 }
            finish { specular 0.4 reflection 0.2 } }
}
