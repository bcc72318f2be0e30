// spiral1 and spiral2, unwarped: POV-Ray's exact formulas, so they
// should match pixel for pixel: arms, the default triangle wave, ramp_wave,
// frequency and phase, rotated and scaled.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -9> look_at <0, 0, 0> angle 50 }
light_source { <-5, 8, -10>, rgb 1 }
plane { z, 2 pigment { spiral1 3 color_map { [0 rgb <0.1,0.1,0.4>] [1 rgb <0.9,0.9,0.6>] } } }
sphere { <-2.4, 0.3, 0>, 1.4
  pigment { spiral2 5 scale 0.5 color_map { [0 rgb <1,0.2,0>] [0.5 rgb 1] [1 rgb <0,0.3,1>] } }
  finish { phong 0.5 } }
disc { <2.4, 0.3, -0.5>, -z, 1.5
  pigment { spiral1 4 ramp_wave frequency 2 phase 0.3 scale 0.8
            color_map { [0 rgb <0,0.5,0.2>] [1 rgb <1,1,0.9>] } } }
box { <-1.5, -3, -1.5>, <1.5, -1.5, 1.5> rotate y*30
  pigment { spiral2 2 rotate x*90 scale 0.6 color_map { [0 rgb <0.6,0,0.4>] [1 rgb <1,0.9,0.2>] } } }
