// Spotlights in scattering media (camlray's whitted mode, POV-Ray 3.7's
// sampling, method 3): each ray's stretch through media is cut where it
// enters and leaves each spotlight's cone, and the pieces are sampled on
// their own, so thin beams are neither missed nor smeared. A hazy
// atmosphere (Mie scattering, two intervals) inside a closed hollow room;
// three beams, one soft-edged and dimmed by the haze on its way, one
// crossing a sphere that casts a shaft of shadow, one narrow and aimed
// across the view; a hollow box of its own denser medium (a gradient
// density) with a beam through it; a point light that leaves the haze
// alone
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 2, 0> angle 62 }

media {
  scattering { 2, rgb 0.035 }
  absorption 0.005
  method 3
  intervals 2
  samples 6
}

light_source { <0, 7, -4>, rgb 0.35 media_interaction off shadowless }

light_source { <-4, 7.5, 1>, rgb <1, 0.45, 0.3> * 2.2
  spotlight point_at <-1.5, 0, 0> radius 8 falloff 16 tightness 5
  media_attenuation on }
light_source { <1.5, 7.8, 1.5>, rgb <0.4, 0.8, 1> * 2
  spotlight point_at <1.2, 0, 0.5> radius 10 falloff 12 tightness 0 }
light_source { <6, 4, -1>, rgb <1, 1, 0.6> * 3
  spotlight point_at <-6, 1, 2> radius 3 falloff 4 }

sphere { <1.25, 3.4, 0.8>, 0.6 pigment { rgb <0.9, 0.9, 0.85> } finish { ambient 0.1 diffuse 0.7 } }
box { <-3.4, 0, -1.2>, <-0.6, 2.2, 1.2>
  pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow
  interior { media { scattering { 1, rgb <0.25, 0.2, 0.1> } absorption 0.05
    density { gradient y color_map { [0 rgb 1] [1 rgb 0.1] } scale 2.2 }
    method 3 samples 8 } } }
cylinder { <2.5, 0, 2>, <2.5, 1.4, 2>, 0.5 pigment { rgb <0.3, 0.6, 0.3> } }

box { <-8, 0, -12>, <8, 8, 6>
  pigment { rgb 0.85 } finish { ambient 0.15 diffuse 0.6 } hollow }
