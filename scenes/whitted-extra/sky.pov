#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -4> look_at <0, 1, 0> }
light_source { <4, 6, -5>, rgb 1 }
background { rgb <0.3, 0, 0> }
sky_sphere {
  pigment { gradient y color_map { [0 rgb <0.9, 0.9, 1>] [0.6 rgb <0.1, 0.3, 0.8>] } }
  pigment { gradient x color_map { [0 rgbt <1,1,1,1>] [0.5 rgbt <1,1,0,0.5>] [1 rgbt <1,1,1,1>] } scale 0.5 }
  rotate z*10 translate y*0.1  // transforms act on the direction as on a point
}
sphere { <0, 1, 0>, 1 pigment { rgb 1 } finish { reflection 0.5 } }
