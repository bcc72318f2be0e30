// uv_mapping: patterns taken at the surface's <u, v, 0>: a checker on a
// turned sphere, a gradient cross on a box, a checker on a torus and a
// mesh2 with uv_vectors, under a texture-level and an object-level
// uv_mapping; the pigments' own transformations scale the uv squares.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3.2, -8> look_at <0, 0.4, 0> angle 48 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -4> rgb 0.35 }
plane { y, -1 pigment { rgb 0.6 } }

sphere { 0, 1
  pigment { uv_mapping checker rgb <0.9, 0.2, 0.1> rgb 0.95 scale <1/12, 1/6, 1> }
  finish { phong 0.5 }
  rotate <20, 30, 0> translate <-2.2, 0.1, 0>
}

box { -0.8, 0.8
  texture { uv_mapping
    pigment { gradient x color_map { [0 rgb <0.1, 0.3, 0.9>] [1 rgb <1, 0.9, 0.3>] } frequency 4 } }
  rotate <-25, 35, 0> translate <0.1, 0, 0>
}

torus { 0.8, 0.3
  pigment { uv_mapping checker rgb <0.2, 0.7, 0.3> rgb 0.95 scale <1/16, 1/6, 1> }
  rotate <-60, 0, 15> translate <2.3, 0.2, 0.3>
}

mesh2 {
  vertex_vectors { 4, <-1, 0, 0>, <1, 0, 0>, <1, 1.4, 0>, <-1, 1.4, 0> }
  uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  uv_mapping
  pigment { radial frequency 6 color_map { [0 rgb <0.5, 0.2, 0.8>] [1 rgb 1] } translate <0.5, 0, 0.5> rotate -x*90 }
  rotate y*-10 translate <0, 1.1, 2.2>
}
