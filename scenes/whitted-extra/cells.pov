// The cells pattern: one value per unit cube, from POV-Ray's own tables
// (so it agrees cell for cell): a colour map, a texture map and a normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0, 0> angle 50 }
light_source { <-6, 10, -8> color rgb 1 }
plane { y, -1
  pigment { cells color_map { [0 rgb <0.1,0.2,0.6>] [0.5 rgb <0.9,0.9,0.8>] [1 rgb <0.8,0.3,0.1>] } scale 0.5 } }
box { <-2.5,-1,-1>, <-0.5,1,1>
  texture { cells texture_map { [0.5 pigment { rgb <0.2,0.7,0.3> }] [0.5 pigment { rgb 0.9 } finish { phong 0.6 }] } scale 0.4 } }
sphere { <1.5, 0, 0>, 1
  pigment { cells scale 0.3 }
  normal { cells 0.15 scale 0.25 } }
