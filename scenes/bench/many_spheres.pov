// Benchmark scene: N random diffuse and reflective spheres over a plane (Declare=N=100000
// on the command line; default 100000), the demo's density scaled up.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 5 }
#ifndef (N) #declare N = 100000; #end
#declare Side = 20 * pow(N / 5000, 1 / 3);
camera { location <0, Side * 0.6, -Side * 1.1> look_at <0, 0, 0> angle 50 }
light_source { <-Side, Side * 2, -Side> color rgb 1 }
light_source { <Side, Side, -Side * 0.5> color rgb 0.4 }
plane { y, -Side / 2 - 0.7 pigment { color rgb 0.6 } finish { reflection 0.2 } }
#declare S = seed(42);
#declare I = 0;
#while (I < N)
  sphere { <rand(S) - 0.5, rand(S) - 0.5, rand(S) - 0.5> * Side, 0.25 + 0.35 * rand(S)
    pigment { color rgb <rand(S), rand(S), rand(S)> }
    finish { phong 0.4 #if (rand(S) < 0.3) reflection 0.4 #end } }
  #declare I = I + 1;
#end
