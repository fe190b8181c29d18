// One scene for every quality level (+Q0 .. +Q9; tests/golden renders it at each): below 2
// surfaces are their pigments, quick_color stands for a pigment up to 5, shadows from 4,
// area lights from 5 (a point at the centre below), refraction from 6, reflection and
// normal { } from 8, fog at 9.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.3, 0> angle 45 }
light_source { <-4, 7, -5> color rgb 1 area_light x*2, y*2, 3, 3 adaptive 1 }
light_source { <4, 5, -3> color rgb 0.4 }
fog { distance 12 color rgb <0.7, 0.7, 0.8> }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1, 0.3, 0.6> scale 0.5
                     quick_colour rgb <0.5, 0.6, 0.7> } }
sphere { <-1.4, 0, 0>, 0.8 pigment { rgbf <0.9, 1, 0.9, 0.8> } interior { ior 1.4 } }
sphere { <0.2, 0, 0.4>, 0.8 pigment { granite quick_color rgb <1, 0, 0> }
         normal { bumps 0.6 scale 0.2 } finish { reflection 0.3 phong 0.6 } }
box { <1, -1, -0.8>, <2.2, 0.4, 0.4>
      texture { pigment { rgb <0.2, 0.8, 0.3> } }
      texture { pigment { checker rgbt <1, 1, 1, 1> rgb <0.9, 0.5, 0.1> scale 0.3 } } }
