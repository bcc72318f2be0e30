// Interior media (camlray's whitted mode, POV-Ray 3.7's sampling): an
// absorbing and emitting box, a sphere glowing with a spherical density,
// a box of scattering medium lit by a light through its clear walls
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -7> look_at <0, 0.6, 0> angle 60 }
background { rgb <0.2, 0.3, 0.5> }
light_source { <4, 8, -3>, rgb 1 }
plane { y, -1 pigment { checker rgb 0.8, rgb 0.3 } }
box { <-3.2, -1, -0.6>, <-1.2, 1, 1.4>
  pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow
  interior { media { absorption <0.2, 0.6, 0.9> emission <0.3, 0.1, 0.02> } } }
sphere { 0, 1 translate <0, 0.2, 0>
  pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow
  interior { media { emission <1, 0.6, 0.2> density { spherical color_map { [0 rgb 0] [1 rgb 1] } } } } }
box { <1.2, -1, -0.6>, <3.2, 1.5, 1.4>
  pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow
  interior { media { scattering { 1, 0.3 } absorption 0.1 } } }
