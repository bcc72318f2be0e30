// bump_map by palette index (use_index) beside the same image by colour:
// POV-Ray takes the palette's indices as heights as they are (0 to 255,
// a steep relief), the colours' grey 0 to 1; test.png is a 4-bit palette
// image of POV-Ray's include folder
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -6> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
light_source { <-6, 4, -8>, rgb 1 }
box { <-1, -1, 0>, <1, 1, 0.2> pigment { rgb 0.8 } normal { bump_map { png "test.png" bump_size 0.1 use_index } translate -(x+y)/2 scale 2 } translate -1.15*x }
box { <-1, -1, 0>, <1, 1, 0.2> pigment { rgb 0.8 } normal { bump_map { png "test.png" bump_size 1 use_color } translate -(x+y)/2 scale 2 } translate 1.15*x }
