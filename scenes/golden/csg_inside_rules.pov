// POV-Ray's inside rules where CSG asks them: a disc is the half-space behind it; a
// difference's later part is inverted but its clips are not (outside its clip, the part
// holds nothing, so the first part's surface there is cut away); a plane's surface is
// inside it and inside its inverse; a quadric's likewise; a torus's surface is inside.
// Parts meeting exactly on such surfaces (a glass rim clipped at the plane its cup ends
// on, a box cut at its own face) keep or drop their faces as POV-Ray does.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 6, -11> look_at <0, 0.3, 0> angle 55 }
light_source { <5, 12, -8> rgb 1 }
light_source { <-8, 6, -4> rgb 0.4 shadowless }
background { rgb <0.15, 0.2, 0.3> }
plane { y, -1.5 pigment { checker rgb 0.8 rgb <0.3, 0.4, 0.6> } }
// A disc cuts a sphere in an intersection, and a box in a difference and in a merge.
intersection {
  sphere { 0, 1 }
  disc { <0, 0.2, 0>, <0, 1, 0.3>, 3 }
  pigment { rgb <1, 0.6, 0.3> } translate <-4, 0, 2>
}
difference {
  box { -0.8, 0.8 }
  disc { 0, <1, 0, 0.2>, 2 }
  pigment { rgb <0.3, 0.6, 1> } rotate 30 * y translate <-1.5, 0, 2>
}
merge {
  sphere { 0, 1 }
  disc { 0, y, 1.5 pigment { rgb <1, 1, 0.5> } }
  pigment { rgbf <0.8, 1, 0.8, 0.7> } interior { ior 1.3 } translate <1.2, 0, 2.5>
}
// The subtracted sphere holds nothing outside its clip: the box's faces there go too.
difference {
  box { -0.9, 0.9 }
  sphere { 0, 1.1 clipped_by { plane { x, 0.3 } } }
  pigment { rgb <0.9, 0.5, 0.6> } rotate 20 * y translate <4, 0, 2>
}
// A glass cup ending on y = 0 with a rim torus clipped at the same plane, merged, and a
// box cut at its own top face by a plane, clipped by an inverse plane at its bottom.
#declare Cup = intersection {
  plane { y, 0 }
  quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, 0 }
  quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.04 inverse }
  clipped_by { plane { y, -1 inverse } }
}
merge {
  object { Cup }
  torus { 0.9, 0.1 clipped_by { plane { -y, 0 } } }
  pigment { rgbf <1, 1, 1, 0.9> } finish { reflection 0.1 phong 0.5 }
  interior { ior 1.5 fade_distance 0.2 fade_power 1 }
  scale <1.2, 1.5, 1.2> translate <-2.5, 0.2, -1.5>
}
difference {
  box { <-0.7, -0.7, -0.7>, <0.7, 0.7, 0.7> }
  plane { -y, -0.7 }
  cylinder { <0, -2, 0>, <0, 2, 0>, 0.3 }
  clipped_by { plane { y, -0.7 inverse } }
  pigment { rgb <0.5, 1, 0.5> } rotate <10, 30, 0> translate <0.5, 0, -1.5>
}
// Inverted spheres, planes and a quadric meeting their siblings on their surfaces.
intersection {
  box { -0.8, 0.8 }
  sphere { <0, 0, 0>, 0.8 inverse }
  plane { x, 0 inverse }
  pigment { rgb <1, 0.8, 0.2> } rotate <20, -30, 0> translate <3, 0, -1.5>
}
