// density_file: POV-Ray's spiral.df3 (50x50x5 voxels) as a pigment,
// without interpolation (left) and trilinear (right)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -3.2> look_at <0, 0, 0> angle 50 }
light_source { <-3, 4, -6>, rgb 1 }
#declare Slab = box { <0, 0, 0>, <1, 1, 1> scale <1.4, 1.4, 0.1> translate <0, -0.7, 0> }
object { Slab
  pigment { density_file df3 "spiral.df3" scale <1.4, 1.4, 0.1> translate <0, -0.7, -0.05>
            color_map { [0 rgb <0.05, 0.05, 0.2>] [0.5 rgb <0.9, 0.4, 0.1>] [1 rgb 1] } }
  finish { ambient 0.3 diffuse 0.7 } translate <-1.5, 0, 0> }
object { Slab
  pigment { density_file df3 "spiral.df3" interpolate 1 scale <1.4, 1.4, 0.1> translate <0, -0.7, -0.05>
            color_map { [0 rgb <0.05, 0.05, 0.2>] [0.5 rgb <0.9, 0.4, 0.1>] [1 rgb 1] } }
  finish { ambient 0.3 diffuse 0.7 } translate <0.1, 0, 0> }
