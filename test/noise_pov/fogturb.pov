#version 3.7;
// A constant and a ground fog with turbulence over surfaces of ambient
// colour only (what POV-Ray shows is the fogs' blend of it), for
// camlray's test_fog (pov_turbulence): rendered 32x24 without
// anti-aliasing into a 16-bit linear PPM (File_Gamma=1), its pixels
// written as text by fogturb.sh
global_settings { assumed_gamma 1 }
camera { location <0, 1, -3> look_at <0, 0.9, 0> angle 70 }
fog { distance 8 color rgb <0.5, 0.4, 0.3> turbulence <0.7, 0.5, 0.9> turb_depth 0.7 octaves 5 omega 0.6 lambda 2.2 }
fog { fog_type 2 distance 5 fog_offset 0.4 fog_alt 0.8 color rgb <0.1, 0.2, 0.4> turbulence 1.3 }
plane { -z, -4 pigment { rgb <0.1, 0.2, 0.3> } finish { ambient 1 diffuse 0 } }
plane { y, 0 pigment { rgb <0.6, 0.1, 0.1> } finish { ambient 1 diffuse 0 } }
sphere { <0.6, 0.8, 0.5>, 0.5 pigment { rgb <0.1, 0.7, 0.2> } finish { ambient 1 diffuse 0 } }
