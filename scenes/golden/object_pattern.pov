// The object pattern: 1 inside its object (a CSG with an inverse part, a text, a
// transformed shape), 0 outside; colour and pigment entries, the default colours, a
// normal with normal entries and without, and a texture with texture entries; the
// pattern's own transforms move the object with it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -10> look_at <0, 0, 0> angle 55 }
light_source { <-10, 20, -20> color rgb 1 }
#declare Lit = finish { ambient 0.3 diffuse 0.7 }
#declare Shape = difference { sphere { 0, 1 } cylinder { -2 * z, 2 * z, 0.5 } }
box { <-1.5, -1.5, -0.2>, <1.5, 1.5, 0.2>
      pigment { object { Shape rgb <0.2, 0.3, 0.9>, rgb <1, 0.8, 0.2> } scale 1.3 }
      finish { Lit } rotate 20 * y translate <-3.3, 1.6, 0> }
box { <-1.5, -1.5, -0.2>, <1.5, 1.5, 0.2>
      pigment { object { sphere { 0, 1 scale <1.4, 0.6, 1> rotate 30 * z }
                         pigment { checker rgb 0 rgb 1 scale 0.25 },
                         pigment { gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 1, 0>] } } } }
      finish { Lit } translate <0, 1.6, 0> }
box { <-1.5, -1.5, -0.2>, <1.5, 1.5, 0.2>
      pigment { object { box { -0.5, 0.5 } rotate 45 * z } }
      finish { Lit } translate <3.3, 1.6, 0> }
box { <-1.5, -1.5, -0.2>, <1.5, 1.5, 0.2>
      pigment { rgb 0.8 }
      normal { object { Shape normal { bumps 0.8 scale 0.1 }, normal { granite 0.3 } } }
      finish { Lit } translate <-3.3, -1.6, 0> }
box { <-1.5, -1.5, -0.2>, <1.5, 1.5, 0.2>
      pigment { rgb <0.9, 0.7, 0.5> }
      normal { object { text { ttf "timrom.ttf" "Po" 1, 0 scale 1.6 translate <-1.1, -0.5, -0.5> } } 0.8 }
      finish { Lit } translate <0, -1.6, 0> }
box { <-1.5, -1.5, -0.2>, <1.5, 1.5, 0.2>
      texture { object { cylinder { -z, z, 1 inverse }
                         texture { pigment { rgb <0.2, 0.7, 0.3> } finish { Lit } },
                         texture { pigment { rgb 1 } finish { Lit phong 0.8 } } } }
      translate <3.3, -1.6, 0> }
