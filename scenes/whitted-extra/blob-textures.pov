// Blob components with textures and transformations of their own.
// Left: two components, red and blue, the blue one stretched into an
// ellipsoid (its field taken in its own space); where both count the
// colours mix by each component's share of the field. Middle: a
// cylinder with a checker moved by the component's scale written after
// it, a sphere without a texture (it takes the blob's green), a carving
// component of negative strength turned and stretched, whose yellow
// still shows (the weights are the fields' absolute values); the whole
// blob turned, its components' textures turned with it. Right: a blob
// in a union that gives it its texture (to the components without one of
// their own), an orange component, and one with only a finish: as in
// POV-Ray, its texture starts from the default texture (black), not
// from the blob's.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -8.5> look_at <0, 0.6, 0> angle 56 }
light_source { <-5, 9, -7> rgb 1 }
light_source { <6, 5, -4> rgb 0.4 }
plane { y, -0.9 pigment { checker rgb 0.8 rgb 0.55 } }

blob {
  threshold 0.5
  sphere { <-0.5, 0, 0>, 1, 1 pigment { rgb <0.9, 0.2, 0.15> } }
  sphere { <0.5, 0, 0>, 1, 1 scale <1, 1.8, 0.8> rotate z*-20 pigment { rgb <0.15, 0.3, 0.9> } }
  finish { phong 0.5 }
  translate <-2.6, 0.3, 0>
}

blob {
  threshold 0.4
  cylinder { <-0.9, 0, 0>, <0.9, 0, 0>, 0.7, 1.2
    pigment { checker rgb <1, 0.85, 0.2> rgb <0.6, 0.2, 0.7> scale 0.5 } scale <1, 1.5, 1> }
  sphere { <0, 0.9, 0>, 0.9, 1.1 }
  sphere { 0, 0.7, -1.5 scale <0.5, 1.6, 0.5> rotate x*-40 translate <-0.4, 0.45, -0.75>
    pigment { rgb <1, 1, 0> } }
  pigment { rgb <0.2, 0.75, 0.3> }
  rotate y*-35 translate <0, 0.2, 0.3>
}

union {
  blob {
    threshold 0.5
    sphere { <0, 0, 0>, 1.1, 1 }
    sphere { <0.3, 1, 0>, 0.8, 1 finish { phong 0.9 phong_size 40 } }
    cylinder { <0, 0, 0>, <0.8, -0.5, -0.5>, 0.5, 1 texture { pigment { rgb <0.9, 0.5, 0.1> } } }
  }
  pigment { rgb <0.7, 0.7, 0.75> }
  translate <2.6, 0.1, 0>
}
