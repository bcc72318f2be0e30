// Syntax forms from POV-Ray's own examples: colours built from channels
// (color blue 1), a trailing comma in a vector, arrays of declared
// materials and normals, a normal's bump size after a comma.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -3> look_at <0, 0.3, 0> }
light_source { <2, 5, -3> rgb 1 }
plane { y, 0 pigment { checker color rgb 1 color blue 1 scale 0.25 } }
sphere { <0, 0.5, 0>, 0.5 pigment { checker color red 1 green 0.5, color blue 0.7 scale 0.2 } }
#declare V = array[2] { <1, 2, 3,>, <4, 5, 6> }
#declare M1 = material { texture { pigment { rgb <1, 0.2, 0.1> } finish { phong 0.8 } } }
#declare M2 = material { texture { pigment { rgb <0.2, 0.8, 0.3> } } }
#declare Ms = array[2] { M1, M2 }
#declare N1 = normal { leopard, 0.5 scale 0.1 }
#declare Ns = array[1] { N1 }
sphere { <1.1, 0.4, 0>, 0.4 pigment { rgb V[0] / 3 } }
sphere { <-1.1, 0.4, 0>, 0.4 material { Ms[0] } }
box { <-0.4, 0, -0.4>, <0.4, 0.8, 0.4> translate <-0.5, 0, 1.2> material { Ms[1] } normal { Ns[0] } }
