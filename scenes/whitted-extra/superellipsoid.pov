// Superellipsoids: from rounded boxes to stars and pillows.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -10.5> look_at <0, 0.6, 0> angle 50 }
light_source { <-6, 10, -8> rgb 1 }
light_source { <7, 5, -3> rgb 0.35 }
plane { y, -0.01 pigment { checker rgb 0.85 rgb 0.55 } }
superellipsoid { <0.2, 0.2> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } translate <-3, 1, 0.5> }
superellipsoid { <1, 1> pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.6 } scale <0.8, 1, 0.8> translate <-1, 1, 0> }
superellipsoid { <2.5, 2.5> pigment { rgb <0.3, 0.4, 0.9> } finish { specular 0.5 roughness 0.02 } rotate <20, 30, 0> translate <1, 1, 0> }
superellipsoid { <0.5, 2> pigment { rgb <0.9, 0.8, 0.2> } finish { phong 0.4 } rotate 90*x translate <3, 1, 0.5> }
