// photons: POV-Ray's photon map. A glass ball focuses the light into a
// bright spot in its shadow (refraction), a mirror ring throws a
// curved caustic on the floor (reflection); the ball's own shadow is
// full, its light comes as photons.
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.02 } }
camera { location <0, 3.5, -5> look_at <0, 0.5, 0> right x*image_width/image_height }
light_source { <-3, 8, 3> rgb 1.2 photons { refraction on reflection on } }
light_source { <3, 5, -6> rgb 0.25 shadowless }
plane { y, 0 pigment { rgb 0.9 } finish { diffuse 0.7 } }
sphere { <-1, 1, 0>, 0.8
  pigment { rgbf <0.95, 1, 0.95, 0.95> } finish { phong 0.9 phong_size 80 reflection { 0.05, 0.3 fresnel } }
  interior { ior 1.5 } photons { target } }
difference {
  cylinder { <0, 0, 0>, <0, 0.6, 0>, 1 }
  cylinder { <0, -0.1, 0>, <0, 0.7, 0>, 0.95 }
  pigment { rgb <1, 0.8, 0.4> } finish { diffuse 0.1 reflection { 0.8 metallic } }
  translate <1.3, 0, 0.6>
  photons { target reflection on collect off } }
