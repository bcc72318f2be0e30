// sor: a closed vase and an open bowl (POV-Ray's surface of revolution)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 1, 0> angle 45 }
light_source { <-6, 10, -8> color rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.5 } }
sor { 7, <0, -0.5>, <0.8, 0>, <1.2, 0.6>, <0.6, 1.6>, <0.5, 2.2>, <0.8, 2.8>, <0.5, 3.2>
  pigment { rgb <0.8, 0.4, 0.2> } finish { phong 0.6 } translate x*-1.6 }
sor { 5, <0, -1>, <0.2, 0>, <1.0, 0.4>, <1.4, 1.1>, <2, 1.5> open
  pigment { rgb <0.3, 0.6, 0.9> } finish { specular 0.5 } translate <1.8, 0.01, 0.5> }
