// Cylindrical lights (light_source { ... cylinder }): rays parallel to
// point_at - location, the light fading with the distance from that
// axis (radius and falloff are distances, not angles; tightness the
// power of 1 - d/falloff), nothing lit behind the plane through the
// light across its axis. A narrow shaft straight down with the defaults
// (radius 0.75, falloff 1) on a sphere and the floor; a wide tilted
// beam (radius 0.5, falloff 1.8, tightness 2) casting the long parallel
// shadow of a post; a level beam toward the back wall from amid two
// blocks (the one behind its plane stays dark) fading along its axis
// (fade_distance, fade_power); a 3x3 area cylinder (each sample's rays
// along the line from point_at through it) with soft shadows; a
// rotated one (its point_at turns with it); shadowless written before
// cylinder (a cylinder casting shadows again)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -10> look_at <0, 1, 0.5> right x*image_width/image_height angle 58 }
background { rgb <0.02, 0.02, 0.05> }

plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.1 diffuse 0.8 } }
plane { -z, -4 pigment { rgb <0.8, 0.75, 0.7> } finish { ambient 0.1 diffuse 0.8 } }
sphere { <-3, 0.7, 1>, 0.7 pigment { rgb <1, 0.6, 0.4> } finish { ambient 0.1 diffuse 0.7 phong 0.6 } }
cylinder { <0.6, 0, 1.2>, <0.6, 1.6, 1.2>, 0.15 pigment { rgb <0.5, 0.8, 0.5> } finish { ambient 0.1 } }
box { <2.6, 0, -2.6>, <3.4, 0.8, -1.8> rotate 20*y pigment { rgb <0.6, 0.6, 1> } finish { ambient 0.1 } }
// two blocks across the level beam, before and behind its light
box { <1.7, 0.6, -1.6>, <2.9, 1.8, -1.4> pigment { rgb 0.9 } finish { ambient 0.1 } }
box { <1.7, 0.6, 1.9>, <2.9, 1.8, 2.1> pigment { rgb 0.9 } finish { ambient 0.1 } }

// a narrow shaft, all defaults but point_at
light_source { <-3, 8, 1>, rgb <1, 0.9, 0.7> cylinder point_at <-3, 0, 1> }

// a wide tilted beam through the post
light_source { <-2.4, 6, 4>, rgb <0.6, 0.8, 1> cylinder point_at <0.6, 0, 1.2>
  radius 0.5 falloff 1.8 tightness 2 }

// level, toward the wall, from amid the blocks; fading along its axis
light_source { <2.2, 1.2, 0>, rgb <1, 0.45, 0.3> * 1.5 cylinder point_at <2.2, 1.2, 4>
  radius 0.4 falloff 0.9 fade_distance 3 fade_power 2 }

// an area cylinder: soft shadows of the box
light_source { <3, 6, -2.2>, rgb <1, 1, 0.6> cylinder point_at <3, 0, -2.2>
  radius 0.9 falloff 1.3 area_light <0.8, 0, 0>, <0, 0, 0.8>, 3, 3 adaptive 1 }

// a small beam turned with its light
light_source { <0, 5, 0>, rgb <0.7, 1, 0.7> cylinder point_at <0, 0, 0> radius 0.2 falloff 0.5
  rotate -25*x translate <-0.8, 0, -1> }

// shadowless, then cylinder: a cylinder casting shadows again
light_source { <-3, 3, -1.5>, rgb 0.6 shadowless cylinder point_at <-3, 0, 0.5> radius 0.3 falloff 0.6 }
