// Spotlights, parallel light, fade, shadowless, a looks_like bulb.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -8> look_at <0, 0.5, 0> }
light_source { <-3, 6, -2>, rgb <1, 0.9, 0.7> spotlight point_at <-2, 0, 1> radius 12 falloff 20 tightness 5 }
light_source { <3, 5, -2>, rgb <0.5, 0.7, 1> spotlight point_at <2, 0, 0> radius 20 falloff 30 fade_distance 4 fade_power 2 }
light_source { <0, 10, -10>, rgb 0.2 parallel point_at 0 }
light_source { <0, 1.2, -3>, rgb 0.3 shadowless }
light_source { <0, 3, 0>, rgb 0.4 looks_like { sphere { 0, 0.2 pigment { rgb <1, 1, 0.6> } finish { ambient 1 diffuse 0 } } } }
plane { y, 0 pigment { rgb 0.8 } }
sphere { <-2, 0.7, 1>, 0.7 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.8 phong_size 80 } }
sphere { <2, 0.7, 0>, 0.7 pigment { rgb <0.3, 0.8, 0.3> } finish { specular 0.6 roughness 0.02 metallic } }
sphere { <0, 0.5, 1.5>, 0.5 pigment { rgb 1 } finish { diffuse 0.8 brilliance 3 } }
