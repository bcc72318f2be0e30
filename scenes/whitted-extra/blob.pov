// Blobs: spheres and cylinders (round ends) of positive strength, one of
// negative strength carving a dent, the old component syntax, a blob in
// a CSG intersection (its inside).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.3, 3, -7.5> look_at <0.3, 0.5, 0> angle 52 }
light_source { <-5, 9, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.35 }
plane { y, -0.8 pigment { checker rgb 0.8 rgb 0.5 } }
blob {
  threshold 0.4
  sphere { <-2.2, 0.5, 0>, 1.1, 1 }
  sphere { <-1.4, 0.5, 0>, 1.1, strength 1 }
  cylinder { <-2.6, -0.2, 0.3>, <-1, 1.3, 0.3>, 0.5, 1.5 }
  sphere { <-1.8, 1.2, -0.6>, 0.6, -2 }
  pigment { rgb <0.85, 0.3, 0.2> } finish { phong 0.7 }
}
blob {
  threshold 0.6
  component 1.0, 1.0, <0.75, 0, 0>
  component 1.0, 1.0, <-0.375, 0.64952, 0>
  component 1.0, 1.0, <-0.375, -0.64952, 0>
  pigment { rgb <0.3, 0.7, 0.35> } finish { specular 0.5 roughness 0.02 }
  rotate <-70, 20, 0> translate <0.6, 0.4, 0>
}
intersection {
  blob { threshold 0.3 cylinder { <-0.8, 0, 0>, <0.8, 0, 0>, 0.9, 1 } cylinder { <0, 0, -0.8>, <0, 0, 0.8>, 0.9, 1 } }
  box { <-2, -0.2, -2>, <2, 2, 2> }
  pigment { rgb <0.3, 0.45, 0.9> } finish { phong 0.4 }
  rotate 30*y translate <2.4, 0, 0.5>
}
