// Area lights with area_illumination: POV-Ray 3.7 finds the shadow as
// for any area light (the samples' shadows averaged, subdividing
// adaptively) with the light's colour unattenuated, then lights the
// point from every sample of the grid (all n1 x n2 of them, whatever
// adaptive says) as from a point light there carrying 1/(n1 n2) of that
// shadowed colour, each with its own direction (diffuse, phong and
// specular), its own fade and spotlight attenuation (the spot's axis
// kept parallel to the light's own), and skipped when it is behind the
// surface. A wide 5x5 light over a shiny sphere and a phong box, a
// spotlight area light (4x4, adaptive 0) on a disc of the floor, and a
// fading oriented circular light low at the side.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.5, -7> look_at <0, 0.6, 0> right x*image_width/image_height }
light_source { <2, 6, -3>, rgb 0.8 area_light <3, 0, 0>, <0, 0, 3>, 5, 5 adaptive 1 area_illumination on }
light_source { <-2, 5, 1>, rgb <1.2, 1, 0.7>
  spotlight point_at <-1.5, 0, 0> radius 12 falloff 22 tightness 4
  area_light <2, 0, 0>, <0, 0, 2>, 4, 4 adaptive 0 area_illumination on }
light_source { <-3.5, 1.2, -2>, rgb <0.4, 0.6, 1> fade_distance 2 fade_power 2
  area_light <1.5, 0, 0>, <0, 1.5, 0>, 5, 5 adaptive 1 circular orient area_illumination on }
plane { y, 0 pigment { rgb 0.75 } }
sphere { <0.3, 1, 0>, 1 pigment { rgb <0.2, 0.5, 0.9> } finish { specular 0.6 roughness 0.02 } }
box { <-2.6, 0, -1.2>, <-1.4, 0.9, 0> pigment { rgb <0.9, 0.6, 0.3> } finish { phong 0.7 phong_size 30 } rotate 20*y }
sphere { <2.2, 0.5, -1.2>, 0.5 pigment { rgb <0.4, 0.8, 0.4> } finish { diffuse 0.7 specular 0.4 roughness 0.05 brilliance 2 } }
