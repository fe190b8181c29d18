// golden-args: --block-mean 8
// Scattering media sampled as POV-Ray samples them at random (method 1, method 2 with
// jitter, method 3 with jitter), in an interior with a density pattern and a point
// light inside the container: compared as 8x8 block means.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -7> look_at <0, 1, 0> angle 55 }
light_source { <0, 1.2, 0.5> color rgb 1 }
light_source { <-5, 8, -5> color rgb 0.6 }
plane { y, 0 pigment { rgb 0.6 } }
#macro Tank(X, Method, Intervals, Samples, Jitter)
  box { <X - 0.9, 0.01, -0.5>, <X + 0.9, 2.4, 1.5> hollow
    pigment { rgbt 1 }
    interior { media { scattering { 2, rgb 0.8 }
      method Method intervals Intervals samples Samples jitter Jitter
      density { spherical scale 1.5 translate <X, 1, 0.5> } } } }
#end
Tank(-2, 1, 8, 4, 0)
Tank(0, 2, 4, 6, 0.5)
Tank(2, 3, 1, 6, 0.4)
