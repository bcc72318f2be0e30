// mesh triangles with their own uv_vectors (flat and smooth) under uv_mapping
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -3> look_at 0 angle 50 }
light_source { <-3, 4, -5> rgb 1 }
mesh {
  triangle { <-1,-1,0>, <1,-1,0>, <1,1,0> uv_vectors <0,0>, <1,0>, <1,1> }
  triangle { <-1,-1,0>, <1,1,0>, <-1,1,0> uv_vectors <0,0>, <1,1>, <0,1> }
  uv_mapping
  texture { pigment { checker rgb <1,0.2,0.1> rgb <0.1,0.3,1> scale 0.25 } finish { ambient 0.2 } }
  rotate <20, 30, 0>
}
mesh {
  smooth_triangle { <-1,-1,0>, -z, <1,-1,0>, -z, <0,1,0>, -z uv_vectors <0.2,0.1>, <0.9,0.3>, <0.5,0.8> }
  uv_mapping
  texture { pigment { gradient x color_map { [0 rgb 0] [1 rgb <1,1,0>] } } }
  scale 0.45 translate <0.9, 0.3, -0.5>
}
