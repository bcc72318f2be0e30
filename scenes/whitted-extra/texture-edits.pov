// pigment { }, normal { } and finish { } change what they are written
// over, as POV-Ray edits in place: a declared texture's pigment moved,
// its finish or normal changed, an object's pigment { } on its texture.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -5> look_at <0, 0.5, 0> }
light_source { <-3, 8, -6> rgb 1 }
#declare T = texture {
  pigment { gradient x color_map { [0 rgb <1, 0.2, 0.1>] [1 rgb <0.1, 0.2, 1>] } }
  finish { phong 0.9 phong_size 20 } }
#declare N = normal { gradient y 0.8 }
plane { y, 0 texture { T pigment { scale 3 rotate 30*y } finish { ambient 0.3 } } }
sphere { <-1.2, 1, 0>, 0.8 texture { T normal { N scale 0.2 } } normal { rotate 45*z } }
sphere { <1.2, 1, 0>, 0.8 texture { T } finish { diffuse 0.9 } pigment { scale 0.6 } }
