// Interior media with 3.7's defaults (method 3, one interval, samples 10): a glowing
// hollow sphere, an absorbing hollow box in front of a checker (and its shadow: interior
// media dim shadow rays through them), and a non-hollow sphere whose media stays dark.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -3> color rgb 1 }
background { color rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.1 } }
sphere { <-1.4, 1, 1>, 0.9 hollow
         pigment { rgbt 1 } interior { media { emission <0.9, 0.5, 0.1> } } }
box { <-0.3, 0, -1.2>, <1.3, 1.6, -0.2> hollow
      pigment { rgbt 1 }
      interior { media { absorption <0.4, 1.2, 2.5> } } }
sphere { <2, 0.7, 1.5>, 0.7
         pigment { rgbt 1 } interior { media { emission 2 } } }
