// Isosurfaces: a bumpy sphere, a torus written with x, y, z, and a
// wavy sheet cut round by its sphere container, left open.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -8> look_at <0, 0.3, 0> angle 50 }
light_source { <-6, 10, -8> rgb 1 }
light_source { <7, 5, -3> rgb 0.35 }
plane { y, -1 pigment { checker rgb 0.85 rgb 0.55 } }
isosurface {
  function { sqrt(x*x + y*y + z*z) - 0.9 + 0.08*sin(8*x)*sin(8*y) }
  max_gradient 1.8
  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 }
  translate <-2.4, 0, 0.3>
}
isosurface {
  function { sqrt(pow(sqrt(x*x + z*z) - 0.8, 2) + y*y) - 0.3 }
  contained_by { box { <-1.2, -0.4, -1.2>, <1.2, 0.4, 1.2> } }
  pigment { rgb <0.3, 0.8, 0.3> } finish { specular 0.5 roughness 0.02 }
  rotate <-35, 20, 0>
}
isosurface {
  function { y - 0.2*sin(4*x)*cos(4*z) }
  contained_by { sphere { 0, 1 } }
  open
  max_gradient 2
  pigment { rgb <0.3, 0.4, 0.9> } finish { phong 0.4 }
  rotate <-70, 20, 0> translate <2.4, 0.2, 0.3>
}
