#!/bin/sh
# Writes the scene probes: one s-NAME.pov per line below (a plane facing
# the camera, lit head-on by a white parallel light, with the pigment
# and finish given; caustics: a bumpy glass plane in front of it (its
# normal towards the floor: POV-Ray turns it), its
# faked caustics on the plane; irid-tir: a glass box on its edge in
# front of it, the light totally reflected inside it iridescent), then POV-Ray 3.7 renders each to a 16-bit linear
# PPM (48 x 36, no anti-aliasing). Run from this folder: sh make-renders.sh
set -e
n=0
while IFS='|' read -r name globals texture; do
  [ -z "$name" ] && continue
  cat > "s-$name.pov" <<POV
#version 3.7;
global_settings { assumed_gamma 1 $globals }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 8*x up 6*y }
light_source { <-30, 20, -100>, rgb 1 parallel point_at <0, 0, 0> }
plane { z, 0 $texture }
POV
  povray -D +W48 +H36 -GA +FP16 File_Gamma=1.0 "+Os-$name.ppm" "s-$name.pov" >/dev/null 2>&1
  n=$((n + 1))
done <<LIST
ripples||pigment { ripples scale 0.7 } finish { ambient 1 diffuse 0 }
ripples-5|number_of_waves 5|pigment { ripples scale 0.7 frequency 1.4 } finish { ambient 1 diffuse 0 }
waves||pigment { waves scale 0.6 phase 0.3 color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0.5, 1>] } } finish { ambient 1 diffuse 0 }
waves-1|number_of_waves 1|pigment { waves scale 0.3 } finish { ambient 1 diffuse 0 }
irid||pigment { rgb 0.45 } finish { ambient 0 diffuse 1 irid { 0.6 thickness 0.4 turbulence 0.7 } }
irid-gen1|noise_generator 1|pigment { rgb 0.45 } finish { ambient 0 diffuse 1 irid { 0.5 thickness 0.3 turbulence 0.9 } }
irid-gen3|noise_generator 3|pigment { rgb 0.45 } finish { ambient 0 diffuse 1 irid { 0.5 thickness 0.3 turbulence 0.9 } }
irid-bumps||pigment { rgb 0.45 } finish { ambient 0 diffuse 1 irid { 0.7 thickness 0.25 turbulence 0.3 } } normal { bumps 0.5 scale 0.3 }
irid-reflect|} background { rgb <0.3, 0.5, 0.7>|pigment { rgb 0.2 } finish { ambient 0 diffuse 0.5 reflection 0.6 irid { 0.5 thickness 0.6 turbulence 0.8 } }
irid-tir||pigment { checker rgb 0.15 rgb 0.5 scale 0.5 } finish { ambient 1 diffuse 0 } } box { <-3, -1.2, -1.2>, <3, 1.2, 1.2> rotate x*35 translate -3*z pigment { rgbf 1 } finish { ambient 0 diffuse 0 irid { 0.8 thickness 0.5 turbulence 0.5 } } interior { ior 1.5 }
caustics||pigment { rgb 0.3 } finish { ambient 0 diffuse 1 } } plane { -z, 2 hollow pigment { rgbf <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0 } interior { caustics 1.2 } normal { bumps 0.6 scale 0.5 }
LIST
echo "$n probes"
