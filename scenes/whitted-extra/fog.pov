// Fog: a constant fog with filter and a transmit floor, a ground fog above
// y = 0.3, both seen in the open and through a hollow glass sphere, none
// seen inside a solid (non-hollow) glass sphere; the sky behind fogged too.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 1.6, -7> look_at <0, 0.8, 4> angle 55 }
light_source { <-8, 12, -6> rgb 1 }
background { rgb <0.2, 0.35, 0.7> }
fog { distance 30 color rgbft <0.7, 0.6, 0.45, 0.3, 0.15> }
fog { fog_type 2 distance 6 fog_offset 0.2 fog_alt 0.25 color rgb <0.75, 0.8, 0.95> }
plane { y, 0 pigment { checker rgb 0.9 rgb <0.6, 0.2, 0.2> scale 2 } }
sphere { <-1.6, 1, 0>, 1 pigment { rgbf <1, 1, 1, 0.9> } finish { reflection 0.1 } interior { ior 1.33 } }
sphere { <1.6, 1, 0>, 1 pigment { rgbf <1, 1, 1, 0.9> } finish { reflection 0.1 } interior { ior 1.33 } hollow }
box { <-3, 0, 10>, <3, 4, 11> pigment { rgb <0.3, 0.8, 0.4> } }
cylinder { <4, 0, 25>, <4, 6, 25>, 1 pigment { rgb 1 } }
