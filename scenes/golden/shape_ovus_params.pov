// ovus: top/bottom radius ratios from 0 to 1.95 (both branches of POV-Ray's band), one
// with sturm, one substituted by a sphere (T >= 2B), and one seen edge-on along the band
// (grazing rays on the torus quartic).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -11> look_at <0, 1, 0> angle 55 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 3, -5> color rgb 0.35 }
plane { y, -1.2 pigment { checker rgb 0.85 rgb 0.55 scale 0.8 } }
#declare F = finish { specular 0.5 roughness 0.02 }
ovus { 1, 0.65 pigment { rgb <0.9, 0.4, 0.3> } finish { F } translate <-4, 0, 2> }
ovus { 1, 0 pigment { rgb <0.3, 0.8, 0.4> } finish { F } translate <-1.5, 0, 2> }
ovus { 1, 1 pigment { rgb <0.3, 0.5, 0.9> } finish { F } rotate <0, 0, 30> translate <1, 0, 2> }
ovus { 0.8, 1.5 sturm pigment { rgb <0.9, 0.8, 0.3> } finish { F } translate <4, -0.2, 2> }
ovus { 1, 0.1 pigment { rgb <0.8, 0.4, 0.9> } finish { F }
       rotate <-60, 20, 0> translate <-3.5, 0.5, -1.5> }
ovus { 0.6, 1.17 pigment { rgb <0.4, 0.9, 0.9> } finish { F }
       scale <1, 0.7, 1.2> rotate <90, 0, 0> translate <0, 0.2, -1.5> }
// T >= 2B: POV-Ray substitutes a sphere of radius T at <0, B, 0>.
ovus { 0.4, 0.9 pigment { rgb <0.9, 0.6, 0.2> } finish { F } translate <3.5, -0.3, -1.5> }
// The band edge-on from the camera's height.
ovus { 1, 0.7 pigment { rgb 0.9 } finish { F } rotate <-20.5, 0, 0> scale 0.8
       translate <0, 3.2, 3> }
