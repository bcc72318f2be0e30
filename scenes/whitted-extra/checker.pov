#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.5, 0> }
light_source { <-5, 8, -6>, rgb 1 }
plane { y, 0 pigment { checker rgb <0.8,0.8,0.8>, rgb <0.1,0.2,0.5> scale 0.75 } }
sphere { <0, 1, 0>, 1 pigment { gradient y color_map { [0 rgb <1,0,0>] [0.5 rgb <1,1,0>] [1 rgb <0,0,1>] } scale 0.5 }
  finish { phong 0.8 phong_size 60 } }
