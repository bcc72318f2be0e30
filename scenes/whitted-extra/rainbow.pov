// POV-Ray's rainbow: a band of colour about the antisolar direction, laid
// over what a ray in the open brings back (the sky, and a far wall seen
// through the distance's fading), cut to an arc with a soft falloff, a
// second bow with filter and transmit in its colours; no jitter.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -10> look_at <0, 3, 0> angle 70 }
light_source { <-20, 30, -20> rgb 1 }
background { rgb <0.35, 0.5, 0.8> }
plane { y, 0 pigment { checker rgb <0.3, 0.6, 0.2> rgb <0.8, 0.8, 0.3> } }
box { <-2, 0, 40>, <8, 6, 41> pigment { rgb <0.7, 0.6, 0.5> } }
sphere { <-2, 1, 0>, 1 pigment { rgb <0.8, 0.1, 0.1> } finish { reflection 0.3 phong 0.8 } }
rainbow {
  angle 30 width 8 distance 60
  direction <0.1, -0.25, 1>
  arc_angle 140 falloff_angle 90
  color_map {
    [0.0 rgbf <1, 0.4, 1, 1>]
    [0.15 rgbf <0.5, 0.3, 1, 0.6>]
    [0.35 rgbf <0.2, 0.4, 1, 0.6>]
    [0.5 rgbf <0.2, 1, 0.3, 0.6>]
    [0.7 rgbf <1, 1, 0.2, 0.6>]
    [0.85 rgbf <1, 0.5, 0.2, 0.6>]
    [1.0 rgbf <1, 0.2, 0.2, 1>]
  }
}
rainbow {
  angle 42 width 4 distance 1e7
  direction <0.1, -0.25, 1> up <0.2, 1, 0>
  color_map { [0 rgbt <1, 1, 1, 0.5>] [0.5 rgbt <1, 0.9, 0.6, 0.2>] [1 rgbt <1, 1, 1, 0.7>] }
}
