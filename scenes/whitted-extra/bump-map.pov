// bump_map: a normal from a small PNG's intensity differences (POV-Ray's
// three-pixel rule), repeated on a plane, bilinear and once on a box
// face, on a sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -4> look_at <0, 0, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1 pigment { rgb 0.7 }
  normal { bump_map { png "bump-map.png" bump_size 0.8 } rotate 90*x scale 1.5 } }
box { <-2.6,-1,-1>, <-0.6,1,1> pigment { rgb <0.9,0.6,0.3> } finish { phong 0.5 }
  normal { bump_map { png "bump-map.png" bump_size 1.5 interpolate 2 once } scale <2,2.2,1> translate <-2.6,-1.1,0> } }
sphere { <1.3, 0, 0>, 1 pigment { rgb <0.5,0.7,0.9> } finish { specular 0.4 }
  normal { bump_map { png "bump-map.png" bump_size 0.5 use_color } scale 0.7 } }
