// Exact patterns (no noise): these should match POV-Ray pixel for pixel.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -9> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 10, -8>, rgb 1 }
plane { y, 0 pigment { hexagon rgb <0.9,0.9,0.8>, rgb <0.3,0.5,0.7>, rgb <0.7,0.3,0.3> scale 0.5 } }
sphere { <-3, 1, 0>, 1 pigment { radial frequency 6 color_map { [0 rgb <1,1,0>] [1 rgb <0,0.3,1>] } } }
sphere { <0, 1, 0>, 1 pigment { onion scale 0.3 color_map { [0 rgb 1] [0.5 rgb <1,0.4,0>] [1 rgb 1] } } finish { phong 0.5 } }
sphere { <3, 1, 0>, 1 pigment { wood scale 0.2 rotate x*60 } }
sphere { <-1.5, 1, 3>, 1 pigment { leopard scale 0.15 color_map { [0 rgb <0.9,0.7,0.2>] [0.5 rgb <0.2,0.1,0>] } } }
sphere { <1.5, 1, 3>, 1 pigment { brick scale 0.05 } }
sphere { <0, 0.5, -2.5>, 0.5 pigment { marble scale 0.3 sine_wave } }
sphere { <-2, 0.5, -2.5>, 0.5 pigment { gradient <1,1,0> color_map { [0 rgbt <1,0,0,0>] [1 rgbt <1,1,1,1>] } scale 0.4 } }
sphere { <2, 0.5, -2.5>, 0.5 pigment { checker pigment { gradient y scale 0.2 }, pigment { rgb <0,0.6,0.2> } scale 0.25 } }
