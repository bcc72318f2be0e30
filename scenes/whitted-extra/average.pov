// average pigment_map: the entries' colours weighted (weights summing
// to their total; a missing weight counts 1), with the whole average
// scaled and a nested map; not as a normal or a texture.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> }
light_source { <-3, 8, -6> rgb 1 }
plane { y, 0 pigment { checker rgb 0.85 rgb 0.45 } }
sphere { <-1.3, 1, 0>, 1
  pigment { average pigment_map {
    [1 gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <1, 1, 0>] }]
    [3 gradient y color_map { [0 rgb <0, 0, 1>] [1 rgb <0, 1, 1>] }]
  } scale 0.5 }
}
box { <0.3, 0, -0.8>, <2.2, 1.9, 0.8>
  pigment { average pigment_map {
    [checker rgb 1 rgb 0 scale 0.5]
    [onion color_map { [0 rgb <0.8, 0.2, 0.1>] [1 rgb <0.1, 0.3, 0.8>] }]
    [2 rgbt <0.2, 0.9, 0.2, 0.3>]
  } rotate 30*y }
}
