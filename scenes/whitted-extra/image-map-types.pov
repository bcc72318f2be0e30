// image_map's map_type 1 (spherical) and 2 (cylindrical), an 8x4 PNG
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -6> look_at <0, 0, 0> angle 45 }
light_source { <-4, 6, -8>, rgb 1 }
sphere { 0, 1 pigment { image_map { png "map-types.png" map_type 1 } } finish { ambient 0.3 } rotate <20, 40, 0> translate <-1.2, 0, 0> }
cylinder { <0,-0.5,0>, <0,1.4,0>, 0.8 pigment { image_map { png "map-types.png" map_type 2 } scale <1, 2, 1> translate -0.5*y } finish { ambient 0.3 } rotate <0, 25, 0> translate <1.3, -0.3, 0> }
