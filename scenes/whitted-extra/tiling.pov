// The 27 tilings of POV-Ray 3.7's tiling pattern, one a tile of the
// floor (1 to 6 at the front, left to right, then 7 to 12 and so on; the
// Penrose ones, 25 to 27, around their centre), each with a colour map of one colour a
// kind of tile and a thin grout band at the top of each kind's band;
// every third tiling also as a normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.35, 14.5, -8.6> look_at <0.1, 0, -0.2> angle 47 }
light_source { <-8, 20, -12> color rgb 1 }
background { rgb <0.1, 0.1, 0.15> }
#declare Kinds = array[27] { 1, 1, 2, 1, 3, 2, 2, 3, 3, 1, 3, 3, 3, 5, 2, 3, 6, 2, 3, 3, 6, 3, 3, 5, 6, 2, 2 }
#declare Colours = array[6] { rgb <0.9, 0.3, 0.2>, rgb <0.2, 0.6, 0.9>, rgb <0.3, 0.8, 0.3>,
                              rgb <0.9, 0.8, 0.2>, rgb <0.7, 0.3, 0.8>, rgb <0.9, 0.6, 0.4> }
#declare N = 1;
#while (N <= 27)
  #declare K = Kinds[N - 1];
  #declare Col = mod(N - 1, 6);
  #declare Row = div(N - 1, 6);
  box { <-0.95, -0.2, -0.95>, <0.95, 0, 0.95>
    texture {
      pigment {
        tiling N
        color_map {
          #declare I = 0;
          #while (I < K)
            [ I / K Colours[I] ]
            [ (I + 0.82) / K Colours[I] * 0.8 ]
            [ (I + 0.86) / K rgb 0.95 ]
            [ (I + 1) / K rgb 0.95 ]
            #declare I = I + 1;
          #end
        }
        #if (N >= 25) scale 0.3 #else scale 0.22 #end
      }
      #if (mod(N, 3) = 0) normal { tiling N 0.6 #if (N >= 25) scale 0.3 #else scale 0.22 #end } #end
      finish { ambient 0.35 diffuse 0.65 }
    }
    translate <(Col - 2.5) * 2, 0, (Row - 2) * 2>
  }
  #declare N = N + 1;
#end
