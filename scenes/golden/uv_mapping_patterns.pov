// uv_mapping of patterns: checker and gradient pigments with their own transforms at the
// surface coordinates, a texture { uv_mapping ... } with a normal, a uv_mapping normal, a
// pigment_map entry under uv_mapping, and the object modifier `uv_mapping` (its textures
// stay on the surface whatever transforms follow, and come down to a CSG's children).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -14> look_at <0, 0.3, 0> angle 50 }
light_source { <-10, 20, -20> color rgb 1 }
#declare Lit = finish { ambient 0.3 diffuse 0.7 }
sphere { 0, 1.3 pigment { uv_mapping checker rgb <1, 0.3, 0.1> rgb <0.1, 0.3, 1> scale <1/12, 1/6, 1> }
         finish { Lit } rotate <30, 20, 0> translate <-4, 1.3, 2> }
box { <-1, -1, -1>, <1, 1, 1>
      texture { uv_mapping pigment { gradient x color_map { [0 rgb <1, 1, 0>] [1 rgb <0, 0.6, 0.2>] }
                                   frequency 4 }
                normal { bumps 0.6 scale 0.05 } finish { Lit } }
      rotate <-25, 35, 0> translate <0, 1.2, 2.5> }
torus { 1, 0.45 pigment { rgb <0.9, 0.8, 0.6> }
        normal { uv_mapping gradient x 1.5 frequency 12 sine_wave }
        finish { Lit specular 0.4 } rotate <-60, 0, 0> translate <4, 1.3, 2> }
// The object modifier: the scale after the texture does not scale the checker.
sphere { 0, 1 uv_mapping
         pigment { checker rgb 1 rgb <0.8, 0.1, 0.3> scale <0.125, 0.25, 1> }
         finish { Lit } scale <1.4, 1, 1> rotate 20 * y translate <-4, 0.2, -2.5> }
// A union's children inherit it with the texture.
union {
  box { <-1, -1, -1>, <1, 1, 1> translate -1.2 * x }
  sphere { 0, 1 translate 1.2 * x }
  uv_mapping
  pigment { gradient y color_map { [0 rgb <0.2, 0.2, 0.9>] [0.5 rgb 1] [1 rgb <0.9, 0.2, 0.2>] }
            frequency 3 }
  finish { Lit }
  scale 0.8 rotate <-20, 10, 0> translate <0.3, 0, -2.5>
}
// pigment_map entries nested in a uv pigment.
cylinder { -y, y, 0.9 open
  pigment { uv_mapping gradient y pigment_map { [0 checker rgb 0 rgb 1 scale 0.1] [1 rgb <1, 0.5, 0>] } }
  finish { Lit } translate <4, 0.2, -2.5> }
plane { y, -1.2 pigment { checker rgb 0.8 rgb 0.5 } }
