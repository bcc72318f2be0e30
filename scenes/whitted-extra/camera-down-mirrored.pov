// A camera looking straight down, along the sky vector, with up z and the
// default direction z: their cross product is 0, a handedness POV-Ray
// takes as left-handed, so the right vector is mirrored (the red sphere
// at +x shows on the left, the green one at +z at the top).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 10, 0> look_at <0, 0, 0> right x*8 up z*6 }
background { rgb 0.2 }
plane { y, 0 pigment { gradient x color_map { [0 rgb <0.3,0,0.6>] [1 rgb <0,0.4,0.8>] } scale 8 translate -4*x } finish { ambient 1 diffuse 0 } }
sphere { <2,0,0>, 0.7 pigment { rgb <1,0,0> } finish { ambient 1 } }
sphere { <0,0,2>, 0.7 pigment { rgb <0,1,0> } finish { ambient 1 } }
sphere { <0,0,0>, 0.5 pigment { rgb <1,1,1> } finish { ambient 1 } }
