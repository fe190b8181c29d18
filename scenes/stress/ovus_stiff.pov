// Ovus at extreme ratios (the band nearly a sphere, nearly a cone, nearly gone), tiny
// and huge, and band rays at grazing angles: the torus quartic is stiff there.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.5, -9> look_at <0, 0.3, 0> angle 45 }
light_source { <10, 20, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
#declare Tops = array[6] { 0.001, 0.05, 0.5, 1, 1.9, 1.999 }
#declare I = 0;
#while (I < 6)
  ovus { 1, Tops[I] pigment { rgb <1, 0.6, 0.2> }
         scale 0.5 rotate <-10 * I, 15 * I, 0> translate <(I - 2.5) * 1.3, 0.8, 0> }
  #declare I = I + 1;
#end
ovus { 1, 0.7 sturm pigment { rgb 1 } scale <3, 0.3, 1> translate <0, -1.3, 2> }
ovus { 1, 0.8 pigment { rgb 0.7 } scale 1e-3 translate <0, -0.6, -8.99> }
ovus { 1, 1.3 pigment { rgb 0.5 } scale 1e3 translate <0, -1.5e3, 4e3> }
