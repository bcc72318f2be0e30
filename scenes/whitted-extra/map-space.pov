// Where a map's entries are taken (POV-Ray 3.7): at the point the map's
// pattern is evaluated at, in its space, after its transformations and
// warps, whatever the order they and the map are written in. Top row,
// pigment_map: scale and rotate written before the map, a repeat warp,
// a nested map; middle row, texture_map: entries with their own normals
// under a non-uniform scale, a black_hole warp, an average and a nested
// map, a checker of textures; bottom row, normal_map: a rotation before
// the map, a repeat warp, a checker of normals.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at 0 right x*image_width/image_height angle 62 }
light_source { <-14, 9, -6>, rgb 1 }
#declare Tile = box { <-1.45, -1.05, -0.1>, <1.45, 1.05, 0.1> }
#declare Flat = finish { ambient 0.25 diffuse 0.75 }
#declare P1 = pigment { checker rgb <0.9, 0.2, 0.1>, rgb <0.1, 0.2, 0.9> scale 0.5 }
#declare P2 = pigment { hexagon rgb <0.2, 0.8, 0.2>, rgb <0.95, 0.9, 0.2>, rgb 0.9 rotate 90*x scale 0.3 }
#declare T1 = texture { pigment { checker rgb <1, 0.4, 0.3>, rgb 0.9 scale 0.4 }
  normal { gradient x 0.6 scale <0.3, 1, 1> } finish { Flat } }
#declare T2 = texture { pigment { rgb <0.3, 0.6, 1> } normal { gradient y 0.5 scale 0.25 rotate 30*z }
  finish { Flat phong 0.6 } }
#declare T3 = texture { pigment { onion color_map { [0 rgb <1, 0.9, 0.3>] [1 rgb <0.5, 0.2, 0.6>] } scale 0.3 } finish { Flat } }

// pigment_map: the scale and rotation before the map scale the entries too
object { Tile pigment { gradient x scale 1.5 rotate 25*z pigment_map { [0.5 P1] [0.5 P2] } } finish { Flat }
  translate <-3.2, 2.4, 0> }
// a repeat warp on the outer pattern: the entries are flipped and shifted with it
object { Tile pigment { gradient x warp { repeat x*0.7 offset y*0.35 flip x } pigment_map { [0.5 P1] [0.5 P2] } scale 1.2 }
  finish { Flat } translate <0, 2.4, 0> }
// nested: the inner map's point is the outer's, in the outer's space
object { Tile pigment { radial rotate -90*x frequency 4 pigment_map { [0.5 P1 scale 2] [0.5 gradient y scale 0.5 pigment_map { [0.5 P2] [0.5 P1 rotate 45*z] }] }
  scale 1.3 translate <0.2, 0.1, 0> } finish { Flat } translate <3.2, 2.4, 0> }

// texture_map: entries' pigments and normals in the map's space
// (stretched and turned: their normals turn with it)
object { Tile texture { gradient x scale <2, 0.7, 1> rotate -30*z texture_map { [0.5 T1] [0.5 T2] } }
  translate <-3.2, 0, 0> }
// a black_hole warp and an average of a nested map
object { Tile texture { gradient y warp { black_hole <0.2, 0.1, 0>, 1.1 strength 1.5 } scale 1.4
    texture_map { [0.5 T1] [0.5 average texture_map { [1 T3] [1 gradient x texture_map { [0.5 T2] [0.5 T1 scale 0.5] } scale 0.6] } rotate 20*z] } }
  translate <0, 0, 0> }
// a checker of textures: scaled and turned, its textures with it
object { Tile texture { checker texture { T1 } texture { T3 } scale 0.8 rotate 10*z } translate <3.2, 0, 0> }

// normal_map: the rotation before the map turns and moves the entries
object { Tile pigment { rgb 0.85 } finish { Flat phong 0.3 }
  normal { gradient x rotate 35*z scale 1.6 normal_map { [0.5 gradient y 3 sine_wave scale 0.3] [0.5 gradient x 3 sine_wave scale 0.2] } }
  translate <-3.2, -2.4, 0> }
// a repeat warp: the entries are mirrored in every other copy
object { Tile pigment { rgb 0.85 } finish { Flat phong 0.3 }
  normal { gradient x warp { repeat x*0.8 flip x } scale 1.5 normal_map { [0.5 gradient x 3 sine_wave scale 0.3] [0.5 onion 3 sine_wave scale 0.25] } }
  translate <0, -2.4, 0> }
// a checker of normals, scaled and turned: its normals with it
object { Tile pigment { rgb 0.85 } finish { Flat phong 0.3 }
  normal { checker normal { gradient y 3 sine_wave scale 0.2 } normal { quilted 1.5 scale 0.15 } scale 0.7 rotate -15*z }
  translate <3.2, -2.4, 0> }
