// Noise patterns and normals: camlray's noise is its own, so these only resemble POV-Ray.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 10, -8>, rgb 1 }
plane { y, 0 pigment { granite scale 2 color_map { [0 rgb 0.3] [1 rgb 0.9] } } normal { bumps 0.3 scale 0.3 } }
sphere { <-3, 1, 0>, 1 pigment { bozo scale 0.3 } }
sphere { <0, 1, 0>, 1 pigment { marble turbulence 0.8 color_map { [0 rgb 0.95] [0.8 rgb <0.5,0.5,0.6>] [1 rgb 0.2] } scale 0.5 } finish { phong 0.6 } }
sphere { <3, 1, 0>, 1 pigment { agate scale 0.5 } }
sphere { <-1.5, 1, 3>, 1 pigment { rgb <0.8,0.2,0.2> } normal { dents 0.8 scale 0.2 } finish { phong 0.8 } }
sphere { <1.5, 1, 3>, 1 pigment { rgb <0.2,0.5,0.9> } normal { ripples 0.6 scale 0.3 } finish { phong 0.8 } }
sphere { <0, 0.6, -2.5>, 0.6 pigment { spotted scale 0.2 } normal { wrinkles 0.5 scale 0.3 } }
