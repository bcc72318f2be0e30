// Area lights with orient: POV-Ray turns the light's grid to face each
// lit point with axes of its own making: d the unit direction from the
// point to the light (a parallel light's along its own axis), the first
// axis along d x z (d x y when d is within 0.01 of +-z), the second
// along d x the first, both as long as the first axis written; an
// oriented light is circular (its parser makes it so), its samples
// moved onto a disc by POV-Ray's own rule (each offset plus 0.001, then
// out to the larger one's distance). Three circular oriented lights,
// 5x5, written with axes not perpendicular to their direction: a warm
// one up on the left, a cool one in front, nearly along -z from the
// objects (the d x y case), and a parallel one from the right; each
// casts soft shadows of the box and the ball
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.6, 0> angle 50 right x*image_width/image_height }
light_source { <-4, 5, -1>, rgb <1, 0.8, 0.6> * 0.8
  area_light <1.6, 1.2, 0>, <0, 1.2, 1.6>, 5, 5 adaptive 1 circular orient }
light_source { <0.2, 0.9, -14>, rgb <0.5, 0.6, 1> * 0.6
  area_light <0, 2, 0>, <1.2, 0, 1.6>, 5, 5 adaptive 1 circular orient }
light_source { <6, 3, 1>, rgb <0.6, 1, 0.6> * 0.5
  parallel point_at <0, 0, 0>
  area_light <0, 1.2, 1.6>, <2, 0, 0>, 5, 5 adaptive 1 circular orient }
plane { y, 0 pigment { rgb 0.85 } finish { ambient 0.05 diffuse 0.8 } }
box { <-0.6, 0, -0.6>, <0.6, 1.4, 0.6> rotate 25*y translate <-1.2, 0, 0.8>
  pigment { rgb <0.9, 0.45, 0.25> } finish { ambient 0.05 diffuse 0.8 } }
sphere { <1.2, 0.9, -0.2>, 0.9 pigment { rgb <0.3, 0.5, 0.9> } finish { ambient 0.05 diffuse 0.8 phong 0.3 } }
box { <-3.5, 0, 2.5>, <3.5, 3, 2.8> pigment { rgb 0.7 } finish { ambient 0.05 diffuse 0.8 } }
