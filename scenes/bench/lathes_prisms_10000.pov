// Benchmark scene: N lathes and prisms (Declare=N=10000 on the command line; default
// 10000) on a floor: vases of each spline kind and extruded outlines of each kind,
// turned and scaled at random, a few of them glass.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 5 }
#ifndef (N) #declare N = 10000; #end
#declare Side = ceil(sqrt(N));
camera { location <Side * 0.5, Side * 0.45, -Side * 0.25> look_at <Side * 0.5, 0, Side * 0.45> angle 60 }
light_source { <Side * 0.2, Side, -Side * 0.3> color rgb 1 }
light_source { <Side, Side * 0.5, -Side * 0.1> color rgb 0.3 }
plane { y, -0.01 pigment { checker color rgb 0.8 color rgb 0.5 scale 2 } }
#declare Vase = array[4] {
  lathe { linear_spline 6, <0, 0>, <0.35, 0>, <0.4, 0.3>, <0.2, 0.6>, <0.3, 0.9>, <0, 0.9> }
  lathe { quadratic_spline 6, <0, 0>, <0.3, 0>, <0.4, 0.4>, <0.15, 0.7>, <0.3, 1>, <0, 1> }
  lathe { cubic_spline 7, <0, -0.1>, <0, 0>, <0.35, 0.1>, <0.2, 0.5>, <0.35, 0.9>, <0, 1>, <0, 1.1> }
  lathe { bezier_spline 8, <0, 0>, <0.5, 0>, <0.1, 0.5>, <0.35, 0.8>, <0.35, 0.8>, <0.3, 1>, <0.1, 1>, <0, 1> }
}
#declare Block = array[4] {
  prism { linear_sweep linear_spline 0, 0.6, 6, <-0.4, -0.3>, <0.4, -0.3>, <0.4, 0.3>, <0, 0.45>, <-0.4, 0.3>, <-0.4, -0.3> }
  prism { linear_sweep quadratic_spline 0, 0.5, 6, <0.4, 0>, <-0.4, 0>, <0, 0.4>, <0.4, 0>, <0, -0.4>, <-0.4, 0> }
  prism { conic_sweep cubic_spline 0.4, 1, 7, <-0.4, -0.4>, <0.4, -0.4>, <0.4, 0.4>, <-0.4, 0.4>, <-0.4, -0.4>, <0.4, -0.4>, <0.4, 0.4> translate -y * 0.4 scale <1, 1.5, 1> }
  prism { bezier_spline 0, 0.4, 8, <-0.4, 0>, <-0.4, 0.5>, <0.4, 0.5>, <0.4, 0>, <0.4, 0>, <0.4, -0.5>, <-0.4, -0.5>, <-0.4, 0> }
}
#declare S = seed(11);
#declare I = 0;
#while (I < N)
  object { #if (mod(I, 2) = 0) Vase[mod(I / 2, 4)] #else Block[mod((I - 1) / 2, 4)] #end
    #if (mod(I, 13) = 0)
      pigment { color rgbf <0.95, 1, 0.95, 0.85> } finish { phong 0.5 } interior { ior 1.5 }
    #else
      pigment { color rgb <rand(S), rand(S), rand(S)> } finish { phong 0.3 }
    #end
    scale 0.6 + 0.5 * rand(S) rotate y * 360 * rand(S)
    translate <mod(I, Side) + 0.5, 0, floor(I / Side) + 0.5> }
  #declare I = I + 1;
#end
