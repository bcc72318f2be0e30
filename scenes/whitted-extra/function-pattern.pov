// Function patterns and pigment functions: a function's value mod 1
// above 1 and mod 1 below 0 (frequency), a declared function as a pattern,
// a function normal, and a pigment function's .red and .gray in a function.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -7> look_at <0, 0.7, 0> angle 50 }
light_source { <-4, 9, -7> rgb 1 }
#declare Ring = function { sqrt(x*x + z*z) * 2 - 3 }
#declare Stripes = function { pigment { gradient x color_map { [0 rgb <1, 0.2, 0>] [1 rgb <0, 0.4, 1>] } scale 0.5 } }
plane { y, 0 pigment { function { Ring(x, y, z) } color_map { [0 rgb 0.9] [0.5 rgb <0.3, 0.5, 0.3>] [1 rgb 0.9] } } }
sphere { <-2.2, 1, 0>, 1
  pigment { function { x*y*3 + z } color_map { [0 rgb <1, 1, 0>] [1 rgb <0.2, 0, 0.6>] } }
  finish { phong 0.4 }
}
sphere { <0, 1, 0.5>, 1
  pigment { rgb <0.9, 0.8, 0.6> }
  normal { function { abs(sin(x*6) * cos(y*6)) } 0.6 }
}
box { <1.4, 0, -1>, <3.2, 1.8, 1>
  pigment { function { Stripes(x, y, z).red * 0.5 + Stripes(x, z, y).gray }
            color_map { [0 rgb <0, 0, 0.3>] [0.6 rgb <1, 0.9, 0.2>] [1 rgb 1] } }
  rotate -20*y
}
