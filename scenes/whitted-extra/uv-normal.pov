// uv-mapped normals: a normal's pattern taken at the surface's <u, v, 0>,
// its slope tilting the world normal as if uv space were world space
// (POV-Ray 3.7, measured). A quilted cloth on a mesh2 (the balcony
// scene's table cloth), wave bands on a turned sphere, a box, a torus,
// a normal_map of uv-mapped entries; transformations after a uv-mapped
// texture turn its normals, after a uv-mapped normal they do nothing.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3.2, -8> look_at <0, 0.4, 0> angle 48 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -4> rgb 0.35 }
plane { y, -1 pigment { rgb 0.6 } }

sphere { 0, 1
  texture { uv_mapping
    pigment { rgb <0.9, 0.5, 0.3> }
    normal { gradient x 0.04 sine_wave scale <1/12, 1, 1> }
    finish { phong 0.6 phong_size 60 }
  }
  scale <1, 1.2, 1> rotate <20, 30, 0> translate <-2.2, 0.1, 0>
}

box { -0.8, 0.8
  pigment { rgb <0.4, 0.6, 0.9> }
  normal { uv_mapping quilted 0.8 control0 0.5 control1 1 scale 1/16 }
  finish { specular 0.4 }
  rotate <-25, 35, 0> translate <0.1, 0, 0>
}

torus { 0.8, 0.3
  uv_mapping
  pigment { rgb <0.3, 0.8, 0.4> }
  normal { gradient y 0.8 triangle_wave scale 1/8 }
  finish { phong 0.5 }
  rotate <-60, 0, 15> translate <2.3, 0.2, 0.3>
}

mesh2 {
  vertex_vectors { 4, <-1, 0, 0>, <1, 0, 0>, <1, 1.4, 0>, <-1, 1.4, 0> }
  uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  texture { uv_mapping
    pigment { rgb 0.95 }
    normal { radial frequency 6 translate <0.5, 0, 0.5> rotate -x*90
      normal_map { [0 gradient x 0.4 sine_wave scale 0.12] [1 quilted 0.6 scale 0.1] } }
    finish { ambient 0.05 diffuse 0.8 }
  }
  scale <1, 1, 0.5> rotate y*-10 translate <0, 1.1, 2.2>
}
