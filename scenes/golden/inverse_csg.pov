// `inverse` on a union: POV-Ray inverts the children and morphs the union into an
// intersection, so the surfaces of one child inside another are gone (a clean bore
// through the box); inverted twice it is a merge. Also an inverted intersection and
// difference.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 0, 0> angle 50 }
light_source { <-4, 6, -5> color rgb 1 }
light_source { <3, 2, -6> color rgb 0.4 }
background { rgb <0.2, 0.3, 0.6> }
#declare Bore = union { cylinder { -2 * z, 2 * z, 0.5 } cylinder { -2 * z, 2 * z, 0.5 translate 0.5 * x } }
intersection { box { -1, 1 } object { Bore inverse } pigment { rgb <0.9, 0.8, 0.5> } translate -2.2 * x }
intersection { box { -1, 1 } union { object { Bore inverse } sphere { <0.2, 0.9, 0>, 0.5 } inverse }
               pigment { rgb <0.5, 0.8, 0.9> } rotate 30 * y }
intersection { sphere { 0, 1.2 } intersection { box { -0.7, 0.7 } sphere { 0, 0.9 } inverse }
               pigment { rgb <0.9, 0.5, 0.7> } translate 2.3 * x }
union { box { -0.3, 0.3 } sphere { 0.3, 0.3 } inverse inverse pigment { rgbf <1, 1, 1, 0.7> }
        interior { ior 1.3 } translate <0, -0.5, -2> }
