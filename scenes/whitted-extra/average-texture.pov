// Averaged textures: texture { average texture_map { [w T] ... } }, each
// entry shaded with its own pigment, normal and finish, the colours
// weighted by w over the weights' sum (entries without a weight: 1).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.6, -6> look_at <0, 0.8, 0> angle 55 }
light_source { <-5, 9, -7>, rgb 1 }
light_source { <6, 5, -4>, rgb 0.35 }

plane { y, 0
  texture { average texture_map {
    [1 pigment { checker rgb <0.9,0.9,0.85>, rgb <0.2,0.3,0.6> scale 0.6 } finish { diffuse 0.8 } ]
    [3 pigment { gradient x color_map { [0 rgb <0.8,0.4,0.1>] [1 rgb <0.1,0.6,0.3>] } scale 2 } finish { diffuse 0.6 ambient 0.2 } ]
  } } }

// a matte, bumped texture averaged with a shiny one
sphere { <-1.6, 1, 0>, 1
  texture { average texture_map {
    [pigment { rgb <1,0.3,0.2> } normal { leopard 0.6 scale 0.25 } finish { diffuse 0.9 }]
    [pigment { gradient y color_map { [0 rgb <0.2,0.2,1>] [1 rgb <1,1,0.3>] } scale 0.5 } finish { phong 1 phong_size 60 }]
  } rotate z*20 } }

// three entries, one of them a texture_map of its own, and a transform
sphere { <1.5, 1, 0.3>, 1
  texture { average texture_map {
    [2 pigment { radial frequency 8 color_map { [0 rgb 1] [1 rgb <0.6,0,0.6>] } } finish { specular 0.6 roughness 0.02 }]
    [1 gradient z texture_map { [0 pigment { rgb <0,0.8,0.2> }] [1 pigment { rgb <0.9,0.9,0> }] } scale 0.7]
    [1 pigment { rgb <0.1,0.1,0.1> } finish { reflection 0.4 }]
  } rotate x*70 translate <1.5, 1, 0.3> } }

// a glass-like average: its shadow passes through both entries' filters
box { <-0.5, 0, -2.2>, <0.5, 1.2, -1.6>
  texture { average texture_map {
    [pigment { rgbf <1, 0.3, 0.3, 0.8> }]
    [pigment { rgbt <0.3, 0.3, 1, 0.5> } finish { phong 0.5 }]
  } } }
