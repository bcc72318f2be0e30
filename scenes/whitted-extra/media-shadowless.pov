// Shadowless lights in media: POV-Ray 3.7 makes a shadowless light a
// fill light, which its media leave out (only point, spot and cylinder
// lights are in the list of lights a ray through media samples): it
// lights surfaces, casts no shadow, and no haze glows in it, whatever
// its media_interaction. A hazy hollow room: a warm shadowless light
// overhead lights the floor and walls; a spotlight written `spotlight
// ... shadowless` is a shadowless point light again (no cone, no beam);
// one written `shadowless spotlight` is a spotlight with shadows, its
// beam in the haze and the ball's shadow shaft in it. Where no beam
// crosses a ray, its media are sampled as unlit (the haze, constant, as
// one stretch; a box of glowing medium with a gradient density, in
// uniform stretches)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 2, 0> angle 62 }

media {
  scattering { 2, rgb 0.04 }
  absorption 0.004
  method 3
  intervals 3
  samples 5
}

light_source { <0, 7, -3>, rgb <1, 0.85, 0.6> * 0.8 shadowless }
light_source { <-5, 7, -2>, rgb <0.5, 1, 0.5>
  spotlight point_at <-3, 0, 1> radius 6 falloff 10 shadowless }
light_source { <2, 7.8, 1>, rgb <0.4, 0.8, 1> * 2.2
  shadowless spotlight point_at <1.2, 0, 0.5> radius 9 falloff 12 tightness 0 }

sphere { <1.5, 3.6, 0.8>, 0.6 pigment { rgb <0.9, 0.9, 0.85> } finish { ambient 0.1 diffuse 0.7 } }
box { <-5.6, 0.2, 1>, <-3.4, 4.5, 3> pigment { rgbt 1 } hollow
  interior { media { emission rgb <0.3, 0.2, 0.1> absorption 0.2 scattering { 1, 0.2 }
    method 3 intervals 3 samples 3
    density { gradient y color_map { [0 rgb 0] [1 rgb 1] } scale 1.5 } } } }
sphere { <-2.5, 1, 0>, 1 pigment { rgb <0.9, 0.4, 0.3> } finish { ambient 0.1 diffuse 0.7 } }
box { <-8, 0, -12>, <8, 8, 6>
  pigment { rgb 0.85 } finish { ambient 0.15 diffuse 0.6 } hollow }
