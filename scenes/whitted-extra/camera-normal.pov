// A camera normal: every ray's direction turned by a normal pattern at
// its screen point, as a surface normal would be (onion rings about the
// image centre and a leopard lattice, no noise).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0>
  normal { average normal_map { [1 onion 0.5 scale 0.2] [1 leopard 0.6 scale 0.06 translate 0.013] } }
  rotate y*10 }
light_source { <-5, 8, -6>, rgb 1 }
plane { y, 0 pigment { checker rgb <0.85,0.85,0.8>, rgb <0.15,0.25,0.5> scale 0.5 } }
plane { z, 3 pigment { gradient x color_map { [0 rgb <0.9,0.6,0.3>] [1 rgb <0.3,0.5,0.8>] } scale 1.5 } }
sphere { <0, 1, 0>, 1 pigment { gradient y color_map { [0 rgb <1,0,0>] [0.5 rgb <1,1,0>] [1 rgb <0,0,1>] } scale 0.5 }
  finish { phong 0.6 phong_size 40 } }
