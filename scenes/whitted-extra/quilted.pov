// quilted with its default controls and with control0/control1 set
// (frequency 0 by default: the value is not wrapped), and with frequency
// and a wave; exact, so it should match POV-Ray pixel for pixel; and
// quilted as a normal (POV-Ray's own perturbation, not the slope).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -8> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 10, -8>, rgb 1 }
plane { y, 0 pigment { quilted scale 0.7 color_map { [0 rgb <0.2,0.1,0.4>] [0.6 rgb <1,0.9,0.7>] } } }
sphere { <-2.5, 1, 0>, 1
  pigment { quilted control0 0 control1 0.5 scale 0.4 color_map { [0 rgb 0] [0.3 rgb <0,0.6,1>] [0.6 rgb 1] } }
  finish { phong 0.6 } }
box { <-1, 0, -2.4>, <1, 0.6, -1.6> pigment { rgb <0.9, 0.85, 0.7> }
  normal { quilted 0.8 control0 0.2 control1 0.9 scale 0.25 } finish { phong 0.5 } }
sphere { <0, 1, 0>, 1
  pigment { quilted control0 -0.3 control1 1.7 scale 0.3 rotate <20,30,0>
            color_map { [0 rgb <0.1,0.4,0>] [1 rgb <1,1,0.3>] } } }
box { <-0.9, 0, -0.9>, <0.9, 1.8, 0.9> rotate y*35 translate x*2.6
  pigment { quilted frequency 3 sine_wave scale 0.5 color_map { [0 rgb <0.7,0,0.2>] [1 rgb <1,0.8,0.8>] } } }
