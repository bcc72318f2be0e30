// finish { irid } with POV-Ray's default irid_wavelength (not set here):
// what POV-Ray 3.7 renders is <0.70, 0.52, 0.48>, not the <0.25, 0.18,
// 0.14> its documentation gives; films on a diffuse sphere, a phong box.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
light_source { <2, 6, -3>, rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
sphere { <-0.9, 1, 0>, 1 pigment { rgb <0.2, 0.5, 0.9> } finish { diffuse 0.6 irid { 0.35 thickness 0.5 } } }
box { <0.4, 0, -0.6>, <1.8, 1.4, 0.6> rotate 25*y pigment { rgb <0.9, 0.7, 0.4> }
  finish { phong 0.7 irid { 0.5 thickness 1.2 } } }
