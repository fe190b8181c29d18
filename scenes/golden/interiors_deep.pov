// A ray inside many objects at once: POV-Ray keeps up to 512 interiors on a ray (its
// RAYINTERIOR_VECTOR_SIZE), each one's media counted and the innermost's ior used, where
// povwall kept 8 (an electric arc macro's dozen glowing spheres lost their media beyond
// the eighth). Twelve overlapping emitting media spheres, and ten nested glass shells
// (each a hollow sphere of its own interior) seen through, with a light among them.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 30 }
camera { location <0, 0.5, -12> look_at <0, 0, 0> angle 40 }
light_source { <-6, 8, -10> color rgb 1 }
background { rgb <0.05, 0.05, 0.1> }
plane { y, -2.5 pigment { checker rgb 0.8 rgb 0.3 } }
#declare I = 0;
#while (I < 12)
  sphere { <-2.2 + I * 0.05, 0.3, 0>, 1.3 pigment { color rgbt 1 } hollow
           interior { media { emission <0.03, 0.02, 0.01> absorption 0.02 } } }
  #declare I = I + 1;
#end
#declare I = 0;
#while (I < 10)
  sphere { <2, 0.2, 0>, 1.6 - I * 0.13
           pigment { rgbf <0.95, 1, 0.95, 0.9> } finish { phong 0.5 }
           interior { ior 1.05 + I * 0.04 fade_distance 2 fade_power 1 } }
  #declare I = I + 1;
#end
