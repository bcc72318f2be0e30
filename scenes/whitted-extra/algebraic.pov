// Polynomial surfaces: a torus written as a quartic, a quadric
// hyperboloid and a cubic saddle (both clipped), a quartic lemniscate seen
// through its bounded_by sphere.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3.5, -9> look_at <0, 0.3, 0> angle 45 }
light_source { <-6, 9, -7> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, -1.2 pigment { checker rgb 0.8 rgb 0.45 } }

// (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2), R = 1, r = 0.35
quartic {
  < 1, 0, 0, 0, 2, 0, 0, 2, 0, -2.245,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    1, 0, 0, 2, 0, 1.755, 0, 0, 0, 0,
    1, 0, -2.245, 0, 0.77000625 >
  sturm
  pigment { rgb <0.9, 0.5, 0.2> } finish { phong 0.6 phong_size 40 }
  rotate <-60, 0, 20> translate <-2.2, 0.2, 0>
}

// x^2 - y^2 + z^2 = 0.15, between y = -1 and y = 1
quadric {
  <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.15
  clipped_by { box { <-2, -1, -2>, <2, 1, 2> } }
  pigment { rgb <0.3, 0.6, 0.9> } finish { specular 0.4 roughness 0.02 }
  scale 0.8 translate <0, 0, 1>
}

// the monkey saddle y = 0.3 (x^3 - 3 x z^2), inside a sphere
cubic {
  < -0.3, 0, 0, 0, 0, 0, 0, 0.9, 0, 0,
    0, 0, 0, 0, 0, 1, 0, 0, 0, 0 >
  sturm
  clipped_by { sphere { 0, 1 } }
  pigment { rgb <0.4, 0.85, 0.4> } finish { phong 0.4 }
  translate <2.2, 0, 0>
}

// x^4 - x^2 + y^2 + z^2 = 0 (a lemniscate turned about the x axis)
quartic {
  < 1, 0, 0, 0, 0, 0, 0, 0, 0, -1,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 1, 0, 0, 0, 0,
    0, 0, 1, 0, 0 >
  sturm
  bounded_by { sphere { 0, 1.05 } }
  pigment { rgb <0.8, 0.3, 0.7> } finish { phong 0.8 }
  scale 0.9 rotate 20*z translate <0, 0.6, -1.8>
}
