// Camera handedness with look_at: a right-handed camera (right -x) and
// the whole scene seen as POV-Ray sees it (up recomputed from the sky,
// right flipped, up not).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <3, 4, -5> right -x*4/3 look_at <0, 0.5, 0> }
light_source { <5, 10, -5> rgb 1 }
box { <-1, 0, -1>, <1, 1, 1> pigment { rgb <0.9, 0.2, 0.1> } }
sphere { <1.5, 1.5, 0>, 0.5 pigment { rgb <0.2, 0.8, 0.3> } }
cone { <-1.5, 0, 0>, 0.5, <-1.5, 2, 0>, 0 pigment { rgb <0.2, 0.3, 0.9> } }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.5 } }
