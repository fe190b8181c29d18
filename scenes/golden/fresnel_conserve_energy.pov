// The nested glass spheres with conserve_energy: what a layer reflects is taken from what
// passes it, per colour channel.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 40 adc_bailout 0.001 }
camera { location <0, 1.5, -6> look_at <0, 0, 0> angle 45 }
light_source { <-4, 6, -5> color rgb 1 }
plane { y, -1.01 pigment { checker color rgb 0.9 color rgb <0.1,0.3,0.6> scale 0.5 } }
#declare I = 0;
#while (I < 5)
  sphere { 0, 1 - I * 0.18
    pigment { rgbf <1, 1, 1, 0.97> }
    finish { reflection { 0.02, 1 fresnel on } conserve_energy ambient 0 diffuse 0 specular 0.8 roughness 0.001 }
    interior { ior (mod(I, 2) = 0 ? 1.5 : 1.33) } }
  #declare I = I + 1;
#end
