// POV-Ray's cylinder camera, type 1: a 270-degree panorama about the up
// vector (the picture is flat up and down, turned across), with a
// reflective ball and a ring of columns around the eye.
#version 3.7;
global_settings { assumed_gamma 1 }
camera {
  cylinder 1
  location <0, 1.5, 0>
  up 1.5*y
  right x*4/3
  angle 270
  look_at <0, 1.2, 5>
}
light_source { <4, 10, -3> rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 } }
#declare I = 0;
#while (I < 12)
  cylinder { 0, 2.5*y, 0.3 translate 5*z rotate I*30*y
    pigment { rgb <0.5 + 0.5*sin(I), 0.5 + 0.5*cos(I), 0.6> } }
  #declare I = I + 1;
#end
sphere { <1.5, 1, 3>, 1 pigment { rgb 0.1 } finish { reflection 0.6 phong 0.8 } }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.8, 0.9, 1>] [1 rgb <0.2, 0.4, 0.8>] } } }
