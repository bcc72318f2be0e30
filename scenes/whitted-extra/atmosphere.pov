// Atmospheric media (scene-level media { }, camlray's whitted mode,
// POV-Ray 3.7's sampling): a scattering, absorbing haze lit by two
// lights (one dimming its shadow rays through the haze, one not
// scattering in it); a hollow sphere holds a declared, edited media
// with a declared density and a density_map, seen under the haze; a clear
// solid box keeps the haze out; a hollow dome of sky closes the scene
// (rays that hit nothing would cross POV-Ray's 2e10 units of haze)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -7> look_at <0, 0.6, 0> angle 60 }
background { rgb <0.3, 0.45, 0.7> }
light_source { <4, 8, -3>, rgb 0.9 media_attenuation on }
light_source { <-6, 5, -6>, rgb 0.4 media_interaction off }
#declare Glow_density = density { spherical }
#declare Glow = media { emission <1, 0.6, 0.2> absorption 0.2 density { Glow_density } }
plane { y, -1 pigment { checker rgb 0.8, rgb 0.3 } }
sphere { 0, 1 translate <0, 0.2, 0>
  pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow
  interior { media { Glow emission <1, 0.5, 0.3>
    density { Glow_density density_map { [0 rgb 0] [0.5 rgb 0.5] [1 rgb 1.5] } } } } }
box { <1.2, -1, -0.6>, <3.2, 1.5, 1.4>
  pigment { rgbf <0.9, 1, 0.9> } finish { ambient 0 diffuse 0 } }
sphere { <-2.2, 0, 0.4>, 1 pigment { rgb <0.9, 0.3, 0.2> } }
sphere { 0, 60 hollow pigment { rgb <0.3, 0.45, 0.7> } finish { ambient 0 diffuse 0 emission 1 } }
#declare Haze = media { scattering { 1, 0.04 } absorption 0.01 }
media { Haze }
