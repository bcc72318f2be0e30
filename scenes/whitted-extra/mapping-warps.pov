// The mapping warps: a checker and gradients wrapped by warp { planar },
// { spherical }, { cylindrical } and { toroidal }, with orientations,
// dist_exp and transformations before and after the warp.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -7> look_at <0, 0.6, 0> angle 50 }
light_source { <-6, 9, -7>, rgb 1 }
light_source { <5, 4, -8>, rgb 0.4 }

// the floor: a checker seen through a planar warp turned to y
plane { y, 0
  pigment { checker rgb <0.85,0.85,0.8>, rgb <0.25,0.3,0.45> scale 0.5 warp { planar y, 0.25 } rotate y*20 } }

// a sphere wrapped in longitude and latitude checks
sphere { <-2.3, 1, 0>, 1
  pigment { checker rgb <0.9,0.2,0.1>, rgb <1,0.9,0.6> scale <1/12, 1/6, 1> warp { spherical } rotate x*-30 translate <-2.3, 1, 0> }
  finish { phong 0.5 phong_size 40 } }

// a cylinder: the turns about y as a gradient, dist_exp spreading it
cylinder { <-0.2, 0, 0>, <-0.2, 2, 0>, 0.8
  pigment { gradient x color_map { [0 rgb <0.1,0.3,0.9>] [0.5 rgb <0.9,0.9,0.2>] [1 rgb <0.1,0.3,0.9>] }
    scale 0.5 warp { cylindrical dist_exp 1 } translate x*-0.2 } }

// a torus in its own warp, the checker around and across the tube
torus { 0.9, 0.35
  pigment { checker rgb <0.2,0.7,0.3>, rgb <0.95,0.95,0.95> scale <1/16, 1/8, 1> warp { toroidal major_radius 0.9 } }
  rotate x*-55 translate <2.1, 1.1, 0> }

// a box: spherical and cylindrical warps turned by orientation
box { <-0.5,-0.5,-0.5>, <0.5,0.5,0.5>
  pigment { gradient y color_map { [0 rgb <1,0.5,0>] [1 rgb <0.2,0,0.5>] } scale 0.2
    warp { cylindrical orientation x } scale 1.5 warp { spherical orientation <0,1,1> dist_exp 0.5 } }
  rotate <20, 35, 0> translate <0.9, 0.5, -2> }
