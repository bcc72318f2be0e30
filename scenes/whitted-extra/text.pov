// TrueType text: kerned pairs (AV, To, Wa) in timrom.ttf, cyrvetic.ttf
// spaced by an offset, and text cut out of a box by CSG (its inside).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <2.4, 1.7, -5.2> look_at <2.4, 0.5, 0> angle 60 }
light_source { <-4, 8, -8> rgb 1 }
light_source { <8, 3, -4> rgb 0.4 }
plane { y, -0.01 pigment { checker rgb 0.85 rgb 0.55 scale 0.5 } }
text { ttf "timrom.ttf" "AVTo Wave" 0.25, 0
  pigment { rgb <0.9, 0.55, 0.2> } finish { phong 0.6 }
  translate <0, 1.1, 0> }
text { ttf "cyrvetic.ttf" "camlray" 0.4, <0.05, 0, 0>
  pigment { rgb <0.3, 0.55, 0.9> } finish { specular 0.5 roughness 0.02 }
  rotate <0, -20, 0> translate <0.1, 0, -0.4> }
difference {
  box { <0, 0, 0>, <1.6, 0.8, 0.3> }
  text { ttf "timrom.ttf" "3.7" 0.5, 0 scale 0.7 translate <0.15, 0.1, -0.1> }
  pigment { rgb <0.5, 0.8, 0.4> }
  translate <3.4, 0, 0.3>
}
