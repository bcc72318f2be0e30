// Blobs and POV-Ray's depth tolerance for them (0.01): a crossing nearer
// than 0.01 to the ray's origin, in the world's units, is not taken; and
// where a component's stretch along the ray starts or ends nearer than
// 0.01 in the blob's own units (before its transformation), that end is
// moved to 0 (a stretch ending there counts nowhere, one starting there
// counts from 0, its field rising again outside the component). A small
// world (the checks are 1 cm): the yellow ball's shadow and reflection
// touch it; the red blob's stop short (the shadow and reflected rays
// that meet it within 0.01 see through it); the green blob, made at half
// size and scaled 2 (spheres, a cylinder, a stretched sphere), casts
// shadows and reflections of shells around its components.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.055, -0.11> look_at <0, 0.008, 0> angle 44 right x*image_width/image_height }
light_source { <-0.6, 0.5, -0.4> rgb 1 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.5 scale 0.01 } finish { reflection 0.25 } }
sphere { <-0.042, 0.006, 0.012>, 0.006 pigment { rgb <0.9, 0.8, 0.3> } }
blob {
  threshold 0.5
  sphere { <-0.02, 0.006, 0>, 0.012, 1 }
  sphere { <-0.008, 0.006, 0>, 0.012, 1 }
  sphere { <-0.014, 0.015, 0.003>, 0.008, 1 }
  pigment { rgb <0.85, 0.3, 0.2> } finish { phong 0.7 }
}
blob {
  threshold 0.5
  sphere { <0.006, 0.003, 0>, 0.006, 1 }
  cylinder { <0.006, 0.003, 0>, <0.016, 0.003, 0.006>, 0.004, 1 }
  sphere { <0, 0, 0>, 0.005, 1 scale <1, 2, 1> translate <0.013, 0.004, -0.003> }
  pigment { rgb <0.3, 0.7, 0.35> } finish { phong 0.7 }
  scale 2
}
