#version 3.7;
#fopen F "dt.txt" write
#declare S = seed(11);
#declare A = 0.001;
#declare FX1 = function { pattern { gradient x warp { turbulence A octaves 1 } } }
#declare FY1 = function { pattern { gradient y warp { turbulence A octaves 1 } } }
#declare FZ1 = function { pattern { gradient z warp { turbulence A octaves 1 } } }
#declare FX6 = function { pattern { gradient x warp { turbulence A octaves 6 omega 0.6 lambda 2.3 } } }
#declare FY6 = function { pattern { gradient y warp { turbulence A octaves 6 omega 0.6 lambda 2.3 } } }
#declare FZ6 = function { pattern { gradient z warp { turbulence A octaves 6 omega 0.6 lambda 2.3 } } }
#for (i, 0, 299)
  #declare P = <int(rand(S)*40)+0.3+0.4*rand(S), int(rand(S)*40)+0.3+0.4*rand(S), int(rand(S)*40)+0.3+0.4*rand(S)>;
  #write (F, str(P.x,0,17), " ", str(P.y,0,17), " ", str(P.z,0,17), " ",
     str(FX1(P.x,P.y,P.z),0,17), " ", str(FY1(P.x,P.y,P.z),0,17), " ", str(FZ1(P.x,P.y,P.z),0,17), " ",
     str(FX6(P.x,P.y,P.z),0,17), " ", str(FY6(P.x,P.y,P.z),0,17), " ", str(FZ6(P.x,P.y,P.z),0,17), "\n")
#end
#fclose F
camera { location -z look_at 0 } sphere { 0, 1 pigment { rgb 1 } }
