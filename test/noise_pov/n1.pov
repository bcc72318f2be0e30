#version 3.7;
global_settings { noise_generator 1 }
#include "functions.inc"
#fopen F "n1.txt" write
#declare S = seed(7);
#for (i, 0, 399)
  #declare P = <rand(S)*40-20, rand(S)*40-20, rand(S)*40-20>;
  #if (i < 40) #declare P = <int(P.x), int(P.y), int(P.z)>; #end
  #write (F, str(P.x,0,17), " ", str(P.y,0,17), " ", str(P.z,0,17), " ", str(f_noise3d(P.x,P.y,P.z),0,17), "\n")
#end
#fclose F
camera { location -z look_at 0 } sphere { 0, 1 pigment { rgb 1 } }
