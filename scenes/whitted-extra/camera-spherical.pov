// POV-Ray's spherical camera: longitude across (300 degrees), latitude
// down (120 degrees), the scene around the eye unrolled onto the image;
// the camera is rotated after look_at.
#version 3.7;
global_settings { assumed_gamma 1 }
camera {
  spherical
  location <0, 1.5, 0>
  angle 300, 120
  look_at <0, 1.5, 1>
  rotate 20*y
}
light_source { <4, 10, -3> rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 } }
#declare I = 0;
#while (I < 10)
  cone { 0, 0.5, 2.5*y, 0 translate 4*z rotate I*36*y
    pigment { rgb <0.5 + 0.5*sin(I), 0.5 + 0.5*cos(I), 0.6> } }
  #declare I = I + 1;
#end
torus { 1, 0.2 rotate 90*x translate <0, 3.5, 3>
  pigment { rgb <0.9, 0.6, 0.2> } finish { phong 0.6 } }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.8, 0.9, 1>] [1 rgb <0.2, 0.4, 0.8>] } } }
