// slope and aoi, the patterns that read the surface: slope's short form and its block
// (low/high ranges, altitude, point_at, an exact axis and an oblique direction), aoi;
// in pigments, a texture_map, a layer under a bumped layer (the pigment sees the
// perturbed normal), a normal, and a filtering shadow caster.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -8> look_at <0, 0.3, 0> angle 55 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -3> color rgb 0.4 }
plane { y, -1
  pigment { checker rgb <0.2, 0.5, 0.2> rgb <0.9, 0.9, 0.85> } }
sphere { <-2.4, 0, 0>, 1
  pigment { slope y color_map { [0 rgb <0.1, 0.1, 0.6>] [0.5 rgb <0.9, 0.9, 0.3>] [1 rgb <0.8, 0.1, 0.1>] } } }
torus { 0.8, 0.35 rotate x * 30 translate <0, 0, 0>
  texture {
    slope { -y * 3, 0, 0.5 altitude y, -0.3, 0.4 }
    texture_map {
      [0.45 pigment { rgb <0.2, 0.6, 0.2> }]
      [0.55 pigment { rgb <0.5, 0.35, 0.2> }]
      [0.65 pigment { rgb <0.5, 0.5, 0.5> } finish { phong 0.5 }]
    } } }
sphere { <2.4, 0, 0>, 1
  pigment { aoi color_map { [0.5 rgb <1, 0.4, 0>] [1 rgb <0, 0.3, 1>] } } }
box { <-3.4, -1, -3>, <-2.2, 0.2, -1.8> rotate y * 25
  pigment { slope { point_at <-6, 6, -8>, 0.3, 0.9 } color_map { [0 rgb 0] [1 rgb <1, 0.8, 0.6>] } } }
sphere { <-0.9, -0.4, -2.2>, 0.6
  texture { pigment { slope <1, 1, 0> color_map { [0 rgb <0.6, 0, 0.6>] [1 rgb <0.9, 1, 0.9>] } } }
  texture { pigment { rgbt <1, 1, 1, 0.6> } normal { bumps 0.8 scale 0.1 } } }
sphere { <0.9, -0.4, -2.2>, 0.6
  pigment { rgb <0.8, 0.8, 0.9> }
  normal { slope { y altitude y } 0.6 scale 0.2 } }
sphere { <2.6, 0.3, -2.4>, 0.7
  pigment { slope -x frequency 2 color_map { [0 rgbf <1, 0.3, 0.3, 0.9>] [1 rgbf <0.3, 0.3, 1, 0.5>] } }
  finish { phong 0.6 } }
