// POV-Ray's fisheye camera: 200 degrees across the circle inscribed in
// the image (right and up set its shape; outside it POV-Ray traces
// nothing and the pixels stay black), looking up from inside a ring of
// arches.
#version 3.7;
global_settings { assumed_gamma 1 }
camera {
  fisheye
  location <0, 1, 0>
  right x*4/3
  angle 200
  look_at <0, 3, 2>
}
light_source { <3, 10, -4> rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.3 } }
#declare I = 0;
#while (I < 8)
  union {
    box { <-0.3, 0, -0.3>, <0.3, 3, 0.3> translate <-1, 0, 4> }
    box { <-0.3, 0, -0.3>, <0.3, 3, 0.3> translate <1, 0, 4> }
    box { <-1.3, 3, -0.3>, <1.3, 3.6, 0.3> translate 4*z }
    pigment { rgb <0.5 + 0.4*sin(I), 0.5 + 0.4*cos(2*I), 0.7> }
    rotate I*45*y
  }
  #declare I = I + 1;
#end
sphere { <0, 6, 2>, 1 pigment { rgb 0.1 } finish { reflection 0.5 phong 0.8 } }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.9, 1>] [1 rgb <0.2, 0.3, 0.8>] } } }
