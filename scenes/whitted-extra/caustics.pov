// interior { caustics }: POV-Ray's faked caustics, the light a shadow ray
// brings through a clear surface raised by |cos|^(45 c) to the normal
// (camlray perturbs it by the layer's normal as it shades; POV-Ray's
// strength there differs): bright cores in glass shadows.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -6> look_at <0, 0.6, 0> }
light_source { <2, 10, -3> rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
sphere { <-1.3, 1, 0>, 0.9
  pigment { rgbf <0.9, 1, 0.9, 0.9> } finish { phong 0.8 }
  interior { ior 1.5 caustics 1 } }
sphere { <1.3, 1, 0>, 0.9
  pigment { rgbf <1, 0.9, 0.8, 0.9> } finish { phong 0.8 }
  interior { ior 1.5 caustics 0.3 } }
box { <-0.4, 0.01, -2.2>, <0.4, 1.2, -1.9>
  pigment { rgbf <0.8, 0.9, 1, 0.95> }
  interior { caustics 2 } rotate 35*y }
