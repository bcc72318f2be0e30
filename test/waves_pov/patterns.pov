// POV-Ray 3.7's ripples and waves patterns at 300 points (run from this
// folder: povray -D +W8 +H6 -GA patterns.pov, then remove patterns.png):
// x y z, then ripples, waves, ripples frequency 2.7 phase 0.3, waves
// frequency 0.6 phase -0.45, ripples sine_wave, waves frequency -1.3
// (17 digits each), into patterns.txt
#version 3.7;
#fopen F "patterns.txt" write
#declare S = seed(23);
#declare R1 = function { pattern { ripples } }
#declare W1 = function { pattern { waves } }
#declare R2 = function { pattern { ripples frequency 2.7 phase 0.3 } }
#declare W2 = function { pattern { waves frequency 0.6 phase -0.45 } }
#declare R3 = function { pattern { ripples sine_wave } }
#declare W3 = function { pattern { waves frequency -1.3 } }
#for (i, 0, 299)
  #declare P = <rand(S)*12-6, rand(S)*12-6, rand(S)*12-6>;
  #write (F, str(P.x,0,17), " ", str(P.y,0,17), " ", str(P.z,0,17), " ",
     str(R1(P.x,P.y,P.z),0,17), " ", str(W1(P.x,P.y,P.z),0,17), " ",
     str(R2(P.x,P.y,P.z),0,17), " ", str(W2(P.x,P.y,P.z),0,17), " ",
     str(R3(P.x,P.y,P.z),0,17), " ", str(W3(P.x,P.y,P.z),0,17), "\n")
#end
#fclose F
camera { location -z look_at 0 } sphere { 0, 1 pigment { rgb 1 } }
