// Fog with turbulence: a constant fog and a ground fog thinned by turbulence (octaves,
// omega, lambda, turb_depth) over a checkered floor and a few spheres.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -8> look_at <0, 1, 0> angle 60 }
light_source { <-10, 20, -15> color rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.85> rgb <0.2, 0.25, 0.3> } }
#for (I, -3, 3)
  sphere { <I * 1.5, 0.8, 4 + 3 * I>, 0.8 pigment { rgb <1, 0.5 + I / 8, 0.2> } }
#end
fog { distance 14 color rgb <0.7, 0.75, 0.8> turbulence <0.5, 0.3, 0.5> octaves 4 turb_depth 0.6 }
fog { fog_type 2 distance 4 color rgbf <0.8, 0.6, 0.5, 0.3> fog_offset 0.3 fog_alt 0.7
      turbulence 0.8 omega 0.6 lambda 2.5 }
