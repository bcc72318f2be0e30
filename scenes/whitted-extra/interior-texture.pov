// interior_texture: the inner side of open and clipped surfaces
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
background { rgb <0.3, 0.35, 0.4> }
plane { y, -1 pigment { checker rgb 0.9, rgb 0.6 } }
sphere { 0, 1.2
  texture { pigment { rgb <0.4, 0.5, 1> } finish { phong 0.5 } }
  interior_texture { pigment { rgb <1, 0.8, 0.1> } }
  clipped_by { plane { y, 0.4 } }
  translate <-1.6, 0.2, 0> }
union {
  cylinder { <0, -1, 0>, <0, 1, 0>, 1 open }
  cone { <0, 1, 0>, 1, <0, 1.6, 0>, 1.5 open }
  texture { pigment { rgb <0.3, 0.8, 0.4> } }
  interior_texture { pigment { gradient y color_map { [0 rgb <1, 0.2, 0.2>] [1 rgb <1, 1, 1>] } scale 3 translate -y } }
  translate <1.6, 0, 0.5> }
