// Object flags: a no_image sphere (not seen, but its shadow and its
// mirror image are), a no_reflection box (seen, shadowed, missing from
// the mirror) and a double_illuminate panel lit from behind.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <4, 3, -6> look_at <0, 1, 1> }
light_source { <-3, 8, -6> rgb 1 }
plane { y, 0 pigment { checker rgb 0.85 rgb 0.45 } }
plane { z, 3 pigment { rgb 0.2 } finish { reflection 0.7 } }
sphere { <-1.2, 1, 0>, 1 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } no_image }
box { <0.3, 0, -0.5>, <1.3, 1.6, 0.5> pigment { rgb <0.2, 0.5, 0.9> } no_reflection }
union {
  box { <2, 0, -1>, <2.05, 2, 1> pigment { rgb <0.9, 0.9, 0.5> } }
  cylinder { <2.6, 0, -2>, <2.6, 1, -2>, 0.3 pigment { rgb <0.4, 0.8, 0.4> } }
  double_illuminate
}
