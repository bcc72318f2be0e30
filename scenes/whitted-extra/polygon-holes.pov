// polygon: outlines closed by returning to their first point; a second
// outline inside the first cuts a hole (even-odd), 2-vector points have
// z = 0; seen tilted, with a shadow through the hole.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -7> look_at <0, 1, 0> }
light_source { <-4, 8, -6> rgb 1 }
plane { y, 0 pigment { checker rgb 0.85 rgb 0.45 } }
polygon {
  9,
  <-2, 0>, <2, 0>, <2, 2.5>, <-2, 2.5>, <-2, 0>,
  <-1, 0.5>, <1, 0.5>, <0, 2>, <-1, 0.5>
  pigment { rgb <0.9, 0.4, 0.2> }
  rotate -20*y translate <-0.5, 0.2, 1>
}
polygon {
  6, <0, 0, 0>, <1, 0, 0.3>, <1.4, 1, 0.42>, <0.5, 1.6, 0.15>, <-0.3, 0.9, -0.09>, <0, 0, 0>
  pigment { rgb <0.2, 0.6, 0.9> } finish { phong 0.5 }
  translate <1.8, 0.3, -1>
}
