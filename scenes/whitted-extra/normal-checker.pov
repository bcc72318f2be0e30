// checker as a normal: POV-Ray 3.7 takes the slope of the 3D checker,
// so where a surface meets a face of the cells (a plane at y = 0) the
// squares of one colour face away, and on a sphere only the cells'
// edges show.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -4.5> look_at <0, 0.4, 0> }
light_source { <-5, 6, -5> rgb 1 }
plane { y, 0 pigment { rgb 0.8 } normal { checker 1 } finish { phong 1 } }
sphere { <-1, 1, 0>, 0.9 pigment { rgb <0.9, 0.7, 0.5> } normal { checker 0.5 scale 0.2 } finish { phong 1 phong_size 60 } }
sphere { <1.1, 1, 0>, 0.9 pigment { rgb <0.6, 0.8, 0.9> } normal { checker 2 scale 0.3 rotate <20, 30, 0> translate 0.05 } finish { specular 0.6 } }
