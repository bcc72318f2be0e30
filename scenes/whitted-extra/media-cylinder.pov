// Cylindrical lights in scattering media (camlray's whitted mode,
// POV-Ray 3.7's sampling, method 3): each ray's stretch through media is
// cut where it enters and leaves each cylinder's beam (POV-Ray's
// interval: within falloff of the axis, from the ray's origin when it
// comes from behind the light's plane), and the pieces are sampled on
// their own. A hazy room; a shaft straight down onto a sphere that
// casts a parallel shadow down the beam; a tilted soft beam (tightness)
// dimmed by the haze on its way (media_attenuation); a level beam
// across the view whose light starts at its own plane; a point light
// that leaves the haze alone
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

light_source { <1.2, 7.9, 0.5>, rgb <0.4, 0.8, 1> * 2
  cylinder point_at <1.2, 0, 0.5> radius 0.5 falloff 0.8 }
light_source { <-4, 7.5, 1>, rgb <1, 0.45, 0.3> * 2.2
  cylinder point_at <-1.5, 0, 0> radius 0.3 falloff 1.2 tightness 2
  media_attenuation on }
light_source { <-2, 5, 1.5>, rgb <1, 1, 0.6> * 2
  cylinder point_at <6, 4.5, 1.5> radius 0.2 falloff 0.35 }

sphere { <1.25, 3.4, 0.6>, 0.4 pigment { rgb <0.9, 0.9, 0.85> } finish { ambient 0.1 diffuse 0.7 } }
cylinder { <2.5, 0, 2>, <2.5, 1.4, 2>, 0.5 pigment { rgb <0.3, 0.6, 0.3> } }

box { <-8, 0, -12>, <8, 8, 6>
  pigment { rgb 0.85 } finish { ambient 0.15 diffuse 0.6 } hollow }
