// Height fields: a 16x16 PGM image (flat triangles, a water level) and a
// function sampled at 40x30 points (smooth normals), non-uniform scales.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -7> look_at <0, 0.3, 0> angle 50 }
light_source { <-6, 10, -8> rgb 1 }
light_source { <7, 5, -3> rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.85 rgb 0.55 } }
height_field { pgm "height-field.pgm" water_level 0.2
  pigment { rgb <0.9, 0.5, 0.2> } finish { phong 0.4 }
  scale <3, 1.2, 3> translate <-3.3, 0, -1> }
height_field { function 40, 30 { 0.5 + 0.4 * sin(x * 9) * cos(y * 7) } smooth
  pigment { rgb <0.3, 0.6, 0.9> } finish { specular 0.5 roughness 0.02 }
  scale <3, 1, 2.5> rotate 20*y translate <0.5, 0, -0.8> }
