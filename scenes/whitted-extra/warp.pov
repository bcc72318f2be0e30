// warps: repeat (offset, flip) and black holes, between transformations
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 50 }
light_source { <-5, 10, -20> color rgb 1 }
#declare Tile = pigment { function { x*x + y } color_map { [0 rgb <0.9, 0.2, 0.1>] [0.5 rgb <1, 0.9, 0.3>] [1 rgb <0.1, 0.2, 0.8>] } }
box { <-4, 0.2, 0>, <-0.2, 3.8, 0.1> pigment { Tile warp { repeat x*0.8 flip y offset <0, 0.2, 0> } } }
box { <0.2, 0.2, 0>, <4, 3.8, 0.1> pigment { checker rgb 1, rgb <0.2, 0.3, 0.6> scale 0.3
  warp { black_hole <2, 2, 0>, 1.5 falloff 3 strength 1.5 } } }
box { <-4, -3.8, 0>, <-0.2, -0.2, 0.1> pigment { gradient x color_map { [0 rgb 0.1] [0.5 rgb 0.9] [1 rgb 0.1] }
  warp { black_hole 0, 0.4 repeat <1, 1, 0> inverse } scale 0.9 rotate z*20 } }
box { <0.2, -3.8, 0>, <4, -0.2, 0.1> pigment { onion color_map { [0 rgb <0.2, 0.6, 0.2>] [1 rgb <0.9, 1, 0.8>] }
  scale 0.5 warp { repeat y*0.7 flip x } translate <2, 0, 0> warp { repeat x } } }
