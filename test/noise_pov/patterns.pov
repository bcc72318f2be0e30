#version 3.7;
// POV-Ray 3.7's pattern values at 300 random points, for camlray's
// test_noise (pov_patterns): each line the point, then each pattern's
// function { pattern { ... } } value, str(v, 0, 17)
#fopen F "patterns.txt" write
#declare S = seed(23);
#declare F0 = function { pattern { bozo noise_generator 1 } };
#declare F1 = function { pattern { bozo noise_generator 2 } };
#declare F2 = function { pattern { bozo noise_generator 3 } };
#declare F3 = function { pattern { spotted } };
#declare F4 = function { pattern { bumps } };
#declare F5 = function { pattern { dents noise_generator 1 } };
#declare F6 = function { pattern { dents } };
#declare F7 = function { pattern { granite noise_generator 1 } };
#declare F8 = function { pattern { granite noise_generator 2 } };
#declare F9 = function { pattern { granite noise_generator 3 } };
#declare F10 = function { pattern { wrinkles noise_generator 1 } };
#declare F11 = function { pattern { wrinkles noise_generator 2 } };
#declare F12 = function { pattern { wrinkles noise_generator 3 } };
#declare F13 = function { pattern { agate } };
#declare F14 = function { pattern { agate agate_turb 0.7 octaves 4 omega 0.6 lambda 2.3 noise_generator 1 } };
#declare F15 = function { pattern { agate turbulence 0.3 noise_generator 3 } };
#declare F16 = function { pattern { marble turbulence 0.7 octaves 5 omega 0.6 lambda 2.2 } };
#declare F17 = function { pattern { marble turbulence 1.3 noise_generator 1 } };
#declare F18 = function { pattern { wood turbulence <0.3, 0.2, 0.1> } };
#declare F19 = function { pattern { wood turbulence 0.05 octaves 3 lambda 2.7 } };
#declare F20 = function { pattern { spiral1 3 turbulence 0.4 } };
#declare F21 = function { pattern { spiral2 2 turbulence 0.2 octaves 3 } };
#declare F22 = function { pattern { bozo turbulence <0.4, 0.6, 0.2> omega 0.7 } };
#declare F23 = function { pattern { crackle } };
#declare F24 = function { pattern { crackle metric 1 } };
#declare F25 = function { pattern { crackle metric 3 form <0.5, 0.4, 0.2> } };
#declare F26 = function { pattern { crackle form <1, 0, 0> offset 0.3 } };
#declare F27 = function { pattern { crackle solid } };
#declare F28 = function { pattern { crackle solid noise_generator 1 } };
#declare F29 = function { pattern { gradient x warp { black_hole <0.3, 0.2, 0.1>, 0.8 repeat <2, 3, 2.5> turbulence <0.5, 0.3, 0.4> } } };
#declare F30 = function { pattern { gradient y warp { black_hole <0.2, 0.1, -0.3>, 6 strength 0.7 falloff 1.5 inverse } } };
#declare F31 = function { pattern { gradient z warp { black_hole <1.5, 0.5, 0.8>, 0.6 turbulence <0.2, 0.2, 0.2> repeat <4, 3, 3> } } };
#declare F32 = function { pattern { bozo warp { turbulence <0.3, 0.5, 0.2> octaves 3 omega 0.7 lambda 1.7 } } };
#declare F33 = function { pattern { crackle metric 1 offset 0.2 } };
#declare F34 = function { pattern { crackle metric 2.5 offset 0.1 form <0.3, 0.6, -0.2> } };
#declare F35 = function { pattern { agate octaves 3 lambda 3 } };
#declare F36 = function { pattern { spiral1 4 turbulence 0.3 noise_generator 1 } };
#declare F37 = function { pattern { marble warp { turbulence 0.5 } } };
#declare F38 = function { pattern { bozo warp { turbulence 0.5 octaves 12 } } };
#declare F39 = function { pattern { marble turbulence 0.5 octaves 0 } };
#declare F40 = function { pattern { gradient x frequency 1.3 phase 0.1 } };
#declare F41 = function { pattern { gradient y poly_wave 1.7 } };
#declare F42 = function { pattern { bozo sine_wave frequency 2 } };
#declare F43 = function { pattern { granite scallop_wave } };
#declare F44 = function { pattern { wrinkles cubic_wave phase 0.35 } };
#declare F45 = function { pattern { gradient z frequency -1.7 } };
#declare F46 = function { pattern { marble ramp_wave frequency 2.3 phase 0.2 } };
#for (i, 0, 299)
  #declare P = <rand(S)*40-20, rand(S)*40-20, rand(S)*40-20>;
  #write (F, str(P.x,0,17), " ", str(P.y,0,17), " ", str(P.z,0,17))
  #write (F, " ", str(F0(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F1(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F2(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F3(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F4(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F5(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F6(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F7(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F8(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F9(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F10(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F11(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F12(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F13(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F14(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F15(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F16(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F17(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F18(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F19(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F20(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F21(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F22(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F23(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F24(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F25(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F26(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F27(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F28(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F29(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F30(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F31(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F32(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F33(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F34(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F35(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F36(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F37(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F38(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F39(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F40(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F41(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F42(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F43(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F44(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F45(P.x,P.y,P.z),0,17))
  #write (F, " ", str(F46(P.x,P.y,P.z),0,17))
  #write (F, "\n")
#end
#fclose F
camera { location -z look_at 0 } sphere { 0, 1 pigment { rgb 1 } }
