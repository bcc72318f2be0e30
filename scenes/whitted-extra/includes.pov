// Standard include files: textures.inc (declared colour maps, layered textures,
// materials), metals.inc. Noise patterns differ from POV-Ray (own noise).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
#include "textures.inc"
#include "metals.inc"
camera { location <0, 3, -7> look_at <0, 0.8, 0> }
light_source { <-4, 8, -6>, rgb 1 }
plane { y, 0 texture { PinkAlabaster } }
sphere { <-2.5, 1, 0>, 1 pigment { Jade } }
sphere { <0, 1, 0>, 1 texture { T_Chrome_3C } }
sphere { <2.5, 1, 0>, 1 material { M_Glass } }
sphere { <-1.2, 0.5, -2>, 0.5 pigment { Cherry_Wood } }
sphere { <1.2, 0.5, -2>, 0.5 texture { T_Gold_2B } }
