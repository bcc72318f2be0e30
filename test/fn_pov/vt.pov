// POV-Ray 3.7's vturbulence(lambda, omega, octaves, V) at 100 points, as
// POV-Ray computes it (run: povray -D +W16 +H16 -GA vt.pov; writes
// vt.txt). Each row: x y z, then the three components of vturbulence for
// each parameter set of the array T (lambda, omega, octaves), in T's
// order; test_value.ml evaluates the same.
#version 3.7;
#declare T = array[7] { <2, 0.5, 6>, <2.3, 0.6, 3>, <1.7, 0.35, 10>, <3, 0.7, 2.9>, <2, 0.5, 25>,
  <2, 0.5, 0.4>, <2.1, 0.45, 1> };
#fopen F "vt.txt" write
#declare S = seed(5);
#for (i, 0, 99)
  #declare P = <rand(S)*40-20, rand(S)*40-20, rand(S)*40-20>;
  #if (i < 10) #declare P = <int(P.x), int(P.y), int(P.z)>; #end
  #if (i >= 10 & i < 30) #declare P = P / 20; #end
  // the point as its 17 decimals read back, so that the row holds it exactly
  #declare P = <val(str(P.x, 0, 17)), val(str(P.y, 0, 17)), val(str(P.z, 0, 17))>;
  #write (F, str(P.x, 0, 17), " ", str(P.y, 0, 17), " ", str(P.z, 0, 17))
  #for (k, 0, 6)
    #declare V = vturbulence(T[k].x, T[k].y, T[k].z, P);
    #write (F, " ", str(V.x, 0, 17), " ", str(V.y, 0, 17), " ", str(V.z, 0, 17))
  #end
  #write (F, "\n")
#end
#fclose F
camera { location -z look_at 0 } sphere { 0, 1 pigment { rgb 1 } }
