// A camera looking straight down, along the sky vector: POV-Ray keeps the
// right vector and turns up to +z (red sphere at +x right, green at +z up).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 10, 0> direction z right (4/3)*x look_at 0 angle 40 }
background { rgb 0.2 }
sphere { <2,0,0>, 0.7 pigment { rgb <1,0,0> } finish { ambient 1 } }
sphere { <0,0,2>, 0.7 pigment { rgb <0,1,0> } finish { ambient 1 } }
sphere { <0,0,0>, 0.5 pigment { rgb <1,1,1> } finish { ambient 1 } }
