// finish { irid { amount thickness t } }: POV-Ray's thin-film colours on
// each light's diffuse and highlights and on the reflected light, with
// irid_wavelength set; films of constant thickness.
#version 3.7;
global_settings { assumed_gamma 1 irid_wavelength rgb <0.25, 0.18, 0.14> }
camera { location <0, 2.5, -6> look_at <0, 0.8, 0> }
light_source { <-4, 8, -6> rgb 1 }
light_source { <5, 3, -4> rgb 0.5 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
sphere { <-1.6, 1, 0>, 1 pigment { rgb 0.7 } finish { phong 0.8 irid { 0.5 thickness 0.6 } } }
sphere { <0.6, 1, 0.5>, 1 pigment { rgb 0.2 }
  finish { reflection 0.6 irid { 0.35 thickness 1.5 } } }
box { <1.8, 0, -1.6>, <3, 1.4, -0.4> rotate 20*y pigment { rgb <0.9, 0.8, 0.6> }
  finish { specular 0.5 irid { 0.8 thickness 0.3 } } }
