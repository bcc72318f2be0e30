// material_map: textures chosen by a palette image's index (numbers past
// the count of textures wrap), repeated on a plane, once on a box face.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -5> look_at <0, 0, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
#declare T0 = texture { pigment { rgb <0.8,0.8,0.7> } }
#declare T1 = texture { pigment { rgb <0.7,0.1,0.1> } finish { phong 0.6 } }
#declare T2 = texture { pigment { checker rgb <0.1,0.3,0.7>, rgb 0.9 scale 0.05 } }
#declare T3 = texture { pigment { rgb <0.9,0.7,0.1> } finish { reflection 0.3 } }
plane { y, -1 texture { material_map { png "material-map.png" texture { T0 } texture { T1 } texture { T2 } texture { T3 } }
  rotate 90*x scale 2 } }
box { <-1.5,-1,-1>, <1.5,1,1>
  texture { material_map { png "material-map.png" once texture { T3 } texture { T2 } texture { T1 } }
    scale <2.1,2.2,1> translate <-1.05,-1.1,0> } }
