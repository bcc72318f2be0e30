#!/bin/sh
# Writes the normal probes: one n-NAME.pov per normal below (a plane facing the
# camera, lit by three parallel lights, red from -x, green from -y, blue
# head-on, so that the three channels give the perturbed normal), then
# POV-Ray 3.7 renders each to a 16-bit linear PPM (48 x 36, no
# anti-aliasing). Run from this folder: sh make-normals.sh
# (bozo, spotted, granite, bumps-map, facets, facets-coords depend on
# POV-Ray's bozo, granite and bumps values and crackle's feature points
# in Pattern.)
set -e
n=0
while IFS='|' read -r name globals normal; do
  [ -z "$name" ] && continue
  cat > "n-$name.pov" <<POV
#version 3.7;
global_settings { assumed_gamma 1 $globals }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 8*x up 6*y }
light_source { <-100, 0, -100>, rgb <1, 0, 0> parallel point_at <0, 0, 0> }
light_source { <0, -100, -100>, rgb <0, 1, 0> parallel point_at <0, 0, 0> }
light_source { <0, 0, -100>, rgb <0, 0, 1> parallel point_at <0, 0, 0> }
plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } normal { $normal } }
POV
  povray -D +W48 +H36 -GA +FP16 File_Gamma=1.0 "+On-$name.ppm" "n-$name.pov" >/dev/null 2>&1
  n=$((n + 1))
done <<LIST
bumps||bumps 0.8 scale 0.5
bumps-slope||bumps 0.6 scale 0.7 slope_map { [0 <0, 1>] [1 <1, 0>] }
bumps-warp||bumps 0.7 scale 0.6 warp { repeat x*1.3 offset <0, 0.5, 0.2> } rotate <10, 20, 30>
dents||dents 1.5 scale 0.4
dents-gen1||dents 1.5 scale 0.4 noise_generator 1
dents-gen3|noise_generator 3|dents 1.5 scale 0.4
wrinkles||wrinkles 1 scale 0.6
ripples||ripples 0.8 scale 0.5 frequency 1.3 phase 0.2
ripples-3|number_of_waves 3|ripples 0.9 scale 0.4
waves||waves 0.8 scale <0.5, 1, 0.3> rotate <20, 30, 10> frequency 0.7
waves-25|number_of_waves 25|waves 0.8 scale 0.4 phase 0.35
quilted||quilted 0.7 scale 0.4 control0 0.3 control1 0.8
leopard-hole||leopard 3 scale 0.2 warp { black_hole <0, 0, 0>, 2.5 strength 1.5 }
gradient-warp||gradient x 2 scale 0.7 warp { spherical orientation y dist_exp 1 } rotate <0, 0, 30>
ripples-map||ripples scale 0.6 normal_map { [0 gradient x, 1 scale 0.3] [1 gradient y, -1 scale 0.4] }
bozo||bozo 1.2 scale 0.3
spotted||spotted 1.2 scale 0.3 slope_map { [0 <0, 0>] [0.5 <1, 0>] [1 <0, -1>] }
granite||granite 0.8 scale 2
bumps-map||bumps scale 0.4 normal_map { [0.3 gradient x, 1 scale 0.3] [0.7 wrinkles 1 scale 0.5] }
facets||facets size 0.6
facets-coords||facets coords 0.7 size 0.5
LIST
echo "$n probes"
