// POV-Ray 3.7 still reads the old finish { ior, refraction } and moves them into the
// object's interior when it is placed: ior bends the rays, refraction scales what passes
// each surface (0.5 twice through a sphere: a quarter). For an object with a plain
// texture the finish's refraction (1 unless given) always replaces interior { refraction
// }; with a patterned texture the interior's value stays.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2, -6> look_at <0, 0.2, 0> angle 48 }
light_source { <-4, 7, -5> color rgb 1 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1, 0.3, 0.6> scale 0.5 } }
sphere { <-1.7, 0, 0>, 0.7 pigment { rgbf <1, 1, 1, 0.9> } finish { refraction 1 ior 1.5 } }
sphere { <-0.55, 0, 0>, 0.5 pigment { rgbt <1, 0.9, 0.8, 0.9> } finish { refraction 0.5 } }
sphere { <0.55, 0, 0>, 0.5 pigment { rgbt <1, 0.9, 0.8, 0.9> } interior { refraction 0.5 } }
sphere { <1.7, 0, 0>, 0.6
         texture { checker texture { pigment { rgbt <1, 0.9, 0.8, 0.9> } }
                           texture { pigment { rgbt <0.8, 0.9, 1, 0.9> } } scale 0.3 }
         interior { ior 1.3 refraction 0.5 } }
union { sphere { <-0.3, 0, 0>, 0.4 } sphere { <0.3, 0, 0>, 0.4 finish { ior 1.2 } }
        pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.6 } translate <0, 0.2, -1.5> }
