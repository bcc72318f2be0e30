// Warps on what has no pattern of its own: an image map, a bump map,
// an average pigment, normal and texture (POV-Ray 3.7 warps their point
// as it warps a pattern's), with transformations before and after the
// warps and a declared pigment warped again where it is used.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -6> look_at 0 right x*4/3 }
light_source { <-5, 5, -8> rgb 1 }
#declare Fin = finish { ambient 0.3 diffuse 0.7 specular 0.4 }

// image map: a black hole, then a repeat; declared, then warped again
#declare P = pigment {
  image_map { png "map-types.png" }
  scale 0.7
  warp { black_hole <0.3, 0.2, 0>, 0.8 strength 1.5 }
  warp { repeat x*0.6 offset y*0.3 flip y }
}
box { <-2.6, 0.05, 0>, <-0.05, 2, 1>
  pigment { P warp { black_hole <0, 0, 0>, 0.5 strength 1 } translate <-1.27, 1.03, 0> }
  finish { Fin } }

// bump map, and an average normal with a warped bump map in it
box { <0.05, 0.05, 0>, <2.6, 2, 1>
  pigment { rgb 0.8 }
  normal {
    average normal_map {
      [1 gradient x 0.5 scale 0.2]
      [1 bump_map { png "bump-map.png" bump_size 2 } warp { black_hole <0.5, 0.5, 0>, 0.4 strength 2 } ]
    }
    warp { repeat y*0.5 offset x*0.2 }
    scale 1.2 translate <1.3, 1, 0>
  }
  finish { Fin } }

// average pigment
box { <-2.6, -2, 0>, <-0.05, -0.05, 1>
  pigment {
    average pigment_map {
      [1 checker rgb 1 rgb 0 scale 0.3]
      [1 gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] }]
    }
    warp { repeat x*0.5 offset y*0.25 }
    rotate z*20
    warp { black_hole <-1.3, -1, 0>, 0.7 strength 1.2 }
  }
  finish { Fin } }

// average texture
box { <0.05, -2, 0>, <2.6, -0.05, 1>
  texture {
    average texture_map {
      [1 pigment { checker rgb 1 rgb <0, 0.5, 0> scale 0.3 } finish { Fin }]
      [1 pigment { gradient y color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } } finish { Fin specular 1 }]
    }
    warp { repeat x*0.5 offset y*0.25 }
    scale 1.1
    warp { black_hole <1.3, -1, 0>, 0.6 strength 1 }
  }
}
