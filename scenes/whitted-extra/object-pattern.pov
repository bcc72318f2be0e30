// The object pattern: 0 outside the object, 1 inside, with colours,
// textures and normals as its two cells; the object moves with the
// pigment (scale) and takes its own modifiers.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.5, -5> look_at <0, 0, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
#declare Star = union { box { <-0.6,-0.6,-0.6>, <0.6,0.6,0.6> rotate 45*y } cylinder { -y, y, 0.3 } }
plane { y, -1 pigment { object { Star scale <1.5,2,1.5> translate <0.6,0,1.2> color rgb <0.2,0.3,0.8> color rgb <1,0.9,0.2> } } }
sphere { <-0.4, 0, 0>, 1
  texture { object { difference { sphere { 0, 1.3 } box { <-2,-0.2,-2>, <2,0.2,2> } }
                     texture { pigment { rgb <0.9,0.2,0.1> } finish { phong 0.5 } }
                     texture { pigment { rgb 0.9 } } } translate -0.4*x }
}
sphere { <1.6, 0, -0.5>, 0.7
  pigment { rgb 0.8 }
  normal { object { sphere { <1.3,0.3,-1.1>, 0.45 } normal { gradient y 0.6 scale 0.2 } normal { gradient x 0.2 } } }
}
box { <-2.6,-1,-1.5>, <-1.8,0.6,-0.7> pigment { object { object { Star scale 0.5 } translate <-2.2, 0.2, -1.5> } } }
