// sor: the documentation's vase closed (both caps) and with sturm, open goblets from
// objects/sor1.pov (the inside seen through the opening), a bulb whose radius closes to
// the axis, and one seen edge-on from its cap's plane (grazing rays on the cubics).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -10> look_at <0, 0.8, 0> angle 50 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 3, -5> color rgb 0.35 }
plane { y, -0.5 pigment { checker rgb 0.85 rgb 0.55 scale 0.8 } }
#declare F = finish { specular 0.5 roughness 0.02 }
#declare Vase = sor { 7, <0.000000, 0.000000> <0.118143, 0.000000> <0.620253, 0.540084>
                         <0.210970, 0.827004> <0.194093, 0.962025> <0.286920, 1.000000>
                         <0.468354, 1.033755> }
object { Vase pigment { rgb <0.9, 0.4, 0.3> } finish { F } scale 2.2 translate <-3.5, -0.5, 1> }
object { Vase sturm pigment { rgb <0.3, 0.8, 0.4> } finish { F } scale 2.2 rotate <-30, 0, 20>
         translate <-1, 0.5, 1> }
sor { 12, <.517241379, -.132625995> <.249336870, 0.000000> <.068965517, .031830239>
          <.021220159, .050397878> <.058355438, .347480106> <.132625995, .381962865>
          <.196286472, .464190981> <.238726790, .602122016> <.249336870, .721485411>
          <.233421751, .864721485> <.167108753, 1.000000000> <.084880637, 1.055702918>
      open pigment { rgb <0.3, 0.5, 0.9> } finish { F } scale 3 rotate <-25, 0, 0>
      translate <1.5, -0.4, 1> }
sor { 11, <0.150754, 0.000000> <0.150754, 0.000000> <0.150754, 0.155779>
          <0.150754, 0.391960> <0.140704, 0.449749> <0.082915, 0.489950>
          <0.125628, 0.530151> <0.140704, 0.582915> <0.047739, 0.919598>
          <0.047739, 1.000000> <0.000000, 1.035176>
      open pigment { rgb <0.9, 0.8, 0.3> } finish { F } scale 3 translate <3.8, -0.5, 1> }
// Radius 0 at both ends: a closed bulb without caps.
sor { 6, <0, -0.3>, <0, 0>, <0.6, 0.4>, <0.3, 0.9>, <0, 1.2>, <0, 1.5>
      pigment { rgb <0.8, 0.4, 0.9> } finish { F } rotate <0, 0, 70> translate <-2.5, 0.2, -2> }
// Edge-on: the camera lies 0.01 above the plane of the top cap.
sor { 5, <0.2, -0.5>, <0.8, 0>, <0.5, 0.5>, <1, 1>, <1.2, 1.5>
      pigment { rgb <0.4, 0.9, 0.9> } finish { F } translate <1.5, 2.99, -2.5> }
