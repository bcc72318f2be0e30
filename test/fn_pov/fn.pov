// POV-Ray 3.7's noise functions of functions.inc at 200 points, written
// as POV-Ray computes them (run: povray -D +W16 +H16 -GA fn.pov; writes
// fn.txt). Each row: x y z, then one value per expression of the array V
// E declares (X, Y, Z standing for the point), in V's order; test_fn.ml
// evaluates the same.
#version 3.7;
#include "functions.inc"
#declare RMF1 = function { internal(59) }
#declare RMF2 = function { internal(59) }
#declare RMF3 = function { internal(59) }
#declare RMF4 = function { internal(59) }
#macro E(X, Y, Z)
  #declare V = array[26] {
    f_noise3d(X, Y, Z), f_snoise3d(X, Y, Z),
    f_noise_generator(X, Y, Z, 0), f_noise_generator(X, Y, Z, 1), f_noise_generator(X, Y, Z, 2),
    f_noise_generator(X, Y, Z, 3), f_noise_generator(X, Y, Z, 4), f_noise_generator(X, Y, Z, 5.7),
    f_noise_generator(X, Y, Z, -1),
    f_ridge(X, Y, Z, 1, 3, 1, 0.2, 0, 0), f_ridge(X, Y, Z, 2.1, 4.5, 0.6, 0.3, 0.7, 2),
    f_ridge(X, Y, Z, 1.9, 6, 0.45, 0.6, 0.4, 3), f_ridge(X, Y, Z, 2, 1, 0.5, 0.5, 0.5, 1),
    RMF1(X, Y, Z, 2, 3, 1, 0.1, 1, 0), RMF2(X, Y, Z, 0.07, 2.2, 7, 0.6, 0.9, 1),
    RMF3(X, Y, Z, 0.1, 3.1, 8, 0.7, 0.8, 2), RMF4(X, Y, Z, 0.5, 2, 3.5, 1, 2, 3),
    f_ridged_mf(X, Y, Z, 0.5, 2, 3, 1, 2, 1), f_ridged_mf(X, Y, Z, 0.9, 3, 4, 1, 2, 1),
    f_hetero_mf(X, Y, Z, 1.1, 2.05, 15, 0.26, 0.01, 1), f_hetero_mf(X, Y, Z, 0.5, 2, 4.5, 0.3, 1, 2),
    f_hetero_mf(X, Y, Z, 0.8, 1.9, 6, 0.7, 2.6, 3), f_hetero_mf(X, Y, Z, 0.25, 2.5, 3, 0.1, 0, 0),
    f_bozo(X, Y, Z), f_dents(X, Y, Z), f_spotted(X, Y, Z)
  };
#end
#fopen F "fn.txt" write
#declare S = seed(23);
#for (i, 0, 199)
  #declare P = <rand(S)*40-20, rand(S)*40-20, rand(S)*40-20>;
  #if (i < 20) #declare P = <int(P.x), int(P.y), int(P.z)>; #end
  #if (i >= 20 & i < 40) #declare P = P / 20; #end
  // the point as its 17 decimals read back, so that the row holds it exactly
  #declare P = <val(str(P.x, 0, 17)), val(str(P.y, 0, 17)), val(str(P.z, 0, 17))>;
  E(P.x, P.y, P.z)
  #write (F, str(P.x, 0, 17), " ", str(P.y, 0, 17), " ", str(P.z, 0, 17))
  #for (k, 0, 25) #write (F, " ", str(V[k], 0, 17)) #end
  #write (F, "\n")
#end
#fclose F
camera { location -z look_at 0 } sphere { 0, 1 pigment { rgb 1 } }
