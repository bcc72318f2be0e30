// a normal's accuracy: the distance of the samples its slope is taken from
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at 0 angle 50 }
light_source { <-5, 6, -8> color rgb 1 }
#declare Tile = box { <-1.2, -1.2, 0>, <1.2, 1.2, 0.1> }
object { Tile pigment { rgb 0.8 } normal { gradient x 1 accuracy 0.1 scale 0.5 } translate <-1.3, 1.3, 0> }
object { Tile pigment { rgb 0.8 } normal { onion 0.8 accuracy 0.2 scale 0.6 } translate <1.3, 1.3, 0> }
object { Tile pigment { rgb 0.8 } normal { leopard 1 accuracy 0.001 scale 0.1 } translate <-1.3, -1.3, 0> }
object { Tile pigment { rgb 0.8 } normal { marble 0.7 accuracy 0.05 scale 0.4 } translate <1.3, -1.3, 0> }
