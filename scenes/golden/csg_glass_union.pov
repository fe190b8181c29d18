// Glass unions: one interior given to the union is shared by its children (their overlap is
// air to a ray, as in POV-Ray), children with their own interiors are entered one after
// the other; filter and transmit; a smaller sphere of another ior nested inside.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }
camera { location <0, 2.2, -6> look_at <0, 0.2, 0> angle 48 }
light_source { <-4, 7, -5> color rgb 1 }
light_source { <5, 3, -4> color rgb 0.4 shadowless }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1, 0.3, 0.6> scale 0.5 } }
union { sphere { <-0.3, 0, 0>, 0.55 } sphere { <0.3, 0, 0>, 0.55 }
  pigment { rgbf <0.9, 1, 0.9, 0.9> } interior { ior 1.5 } translate <-1.6, 0, 0> }
union { sphere { <-0.3, 0, 0>, 0.55 interior { ior 1.5 } }
        sphere { <0.3, 0, 0>, 0.55 interior { ior 1.33 } }
  pigment { rgbt <1, 0.9, 0.8, 0.8> } finish { reflection { 0, 0.6 fresnel } } translate <0, 0, 0> }
union { sphere { 0, 0.7 } sphere { 0, 0.3 interior { ior 1.1 } }
  pigment { rgbf <1, 0.8, 0.8, 0.85> } interior { ior 1.5 } translate <1.6, 0, 0> }
