// Benchmark scene: N text objects (Declare=N=1000 on the command line; default 1000), a
// wall of labels as molecule and chart scenes have them, in three fonts, some glass.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 5 }
#ifndef (N) #declare N = 1000; #end
#declare Columns = ceil(sqrt(N / 2));
#declare Rows = ceil(N / Columns);
camera { location <Columns * 1.2, Rows * 0.5, -Rows * 1.1> look_at <Columns * 1.2, Rows * 0.5, 0> angle 60 }
light_source { <Columns, Rows * 2, -Rows * 2> color rgb 1 }
light_source { <Columns * 3, Rows, -Rows> color rgb 0.4 }
plane { z, 0.5 pigment { color rgb 0.7 } }
#declare Fonts = array[3] { "timrom.ttf", "cyrvetic.ttf", "crystal.ttf" }
#declare S = seed(7);
#declare I = 0;
#while (I < N)
  text { ttf Fonts[mod(I, 3)] concat("T", str(I, 0, 0)) 0.3, 0
    #if (mod(I, 7) = 0)
      pigment { color rgbf <0.9, 0.95, 1, 0.8> } finish { phong 0.6 } interior { ior 1.4 }
    #else
      pigment { color rgb <rand(S), rand(S), rand(S)> } finish { phong 0.4 }
    #end
    translate <mod(I, Columns) * 2.4, floor(I / Columns), -0.3 * rand(S)> }
  #declare I = I + 1;
#end
