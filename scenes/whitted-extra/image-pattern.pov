// image_pattern: a 16 x 16 RGBA PNG's grey (0.297 r + 0.589 g + 0.114 b
// of the file's values, not gamma-decoded) as a pattern: in a pigment's
// colour_map (planar, repeated), in a normal (bilinear, once, on a box
// face), in a texture_map (its alpha with use_alpha, spherical), and
// wrapped round a cylinder (map_type 2) and a torus (map_type 5).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -7> look_at <0, 0.3, 0> angle 50 }
light_source { <-4, 6, -8>, rgb 1 }
light_source { <5, 3, -3>, rgb 0.4 }
// the wall: a colour_map over the grey, the image repeated
plane { z, 2
  pigment { image_pattern { png "image-pattern.png" }
    color_map { [0 rgb <0.05, 0.1, 0.3>] [0.5 rgb <0.8, 0.4, 0.2>] [1 rgb <1, 0.95, 0.7>] }
    scale 1.6 translate <-0.3, -1, 0> }
  finish { ambient 0.2 diffuse 0.8 } }
// the floor: the image's transparency picks a texture
plane { y, -1
  texture { image_pattern { png "image-pattern.png" use_alpha interpolate 4 }
    texture_map {
      [0 pigment { rgb <0.9, 0.9, 0.8> } finish { phong 0.4 ambient 0.15 }]
      [1 pigment { checker rgb <0.2, 0.5, 0.3> rgb <0.1, 0.2, 0.15> scale 0.25 } finish { ambient 0.15 }] }
    rotate 90*x scale 2.5 } }
// a box face tilted by the grey, interpolated, the image once
box { <-1, -1, -0.5>, <1, 1, 0.5>
  pigment { rgb <0.7, 0.75, 0.9> }
  normal { image_pattern { png "image-pattern.png" interpolate 2 once } 1.2 translate <-0.5, -0.5, 0> scale 1.8 }
  finish { phong 0.6 phong_size 30 }
  rotate <0, 20, 0> translate <-1.7, 0.1, 0> }
// a sphere's texture_map over the alpha, wrapped spherically
sphere { 0, 0.8
  texture { image_pattern { png "image-pattern.png" use_alpha map_type 1 }
    texture_map {
      [0.3 pigment { rgb <0.9, 0.2, 0.1> } finish { specular 0.5 }]
      [0.7 pigment { rgb <0.2, 0.3, 0.9> } normal { image_pattern { png "image-pattern.png" map_type 1 interpolate 2 } 0.8 }] } }
  rotate <0, -30, 0> translate <0.3, -0.2, -0.8> }
// round a cylinder and a torus
cylinder { <0, 0, 0>, <0, 1, 0>, 0.5
  pigment { image_pattern { png "image-pattern.png" map_type 2 interpolate 2 } color_map { [0 rgb 0.1] [1 rgb <1, 0.8, 0.3>] } }
  scale <1, 1.6, 1> translate <1.9, -1, 0.3> }
torus { 1, 0.3
  pigment { image_pattern { png "image-pattern.png" map_type 5 } color_map { [0 rgb <0.1, 0.3, 0.1>] [1 rgb <0.7, 1, 0.6>] } }
  scale 0.6 rotate <-60, 0, 0> translate <1.9, 1.3, 0.3> }
