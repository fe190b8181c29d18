// #declare of floats, vectors and colours; #if/#else; #while with seed()/rand(); colors.inc.
#version 3.7;
#include "colors.inc"
global_settings { assumed_gamma 1.0 }
#declare Height = 1.5;
#declare Centre = <0, Height, 0>;
#declare Tint = color Orange * 0.8;
#declare Fancy = yes;
camera { location Centre + <0, 4, -9> look_at Centre angle 50 }
light_source { <4, 10, -6> color White }
#if (Fancy)
  background { color SkyBlue * 0.5 }
#else
  background { color Black }
#end
plane { y, 0 pigment { color Gray60 } }
#declare S = seed(42);
#declare N = 0;
#while (N < 40)
  #declare Pos = <rand(S) * 8 - 4, rand(S) * 3, rand(S) * 6 - 2>;
  sphere { Pos, 0.2 + 0.25 * rand(S)
    #if (mod(N, 3) = 0) pigment { Tint } #else pigment { color rgb <rand(S), rand(S), rand(S)> } #end
    finish { phong 0.5 }
  }
  #declare N = N + 1;
#end
