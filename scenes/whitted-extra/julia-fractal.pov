// julia_fractal: quaternion (sqr, cube) and hypercomplex (sqr) sets
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -6> look_at <0, 0, 0> angle 60 }
light_source { <-5, 8, -10>, rgb 1 }
light_source { <6, -2, -6>, rgb 0.4 }
background { rgb <0.6, 0.7, 0.9> }
julia_fractal { <-0.083, 0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15
  pigment { rgb <1, 0.75, 0.4> } finish { phong 0.6 phong_size 40 }
  rotate <0, 30, 0> translate <-1.9, 1.1, 0> }
julia_fractal { <-0.2, 0.4, -0.4, -0.4> quaternion cube max_iteration 6 precision 20
  pigment { rgb <0.5, 0.9, 0.6> } finish { specular 0.4 }
  rotate <-20, 40, 0> translate <1.9, 1.1, 0> }
julia_fractal { <-0.745, 0, 0.113, 0.05> hypercomplex sqr max_iteration 9 precision 20
  pigment { rgb <0.9, 0.5, 0.6> } finish { phong 0.9 phong_size 20 }
  scale <1, 2, 1> rotate <135, -30, 0> scale 0.55 translate <0, -1.3, 0> }
