// POV-Ray's trace level test meets every ray as it starts, at its parent's level; a ray
// that passes straight through a surface between equal indices of refraction (a filter
// without ior) keeps that level. So at max_trace_level 1 nothing shows through a filter
// (black), and at a higher level a filtered ray that starts at the last level is black too,
// while its reflection is refused one level earlier. Left: max_trace_level 1 behind a
// filter; middle: two filtered mirrors overlapping; right: a stack of five filter slabs.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 3 }
camera { location <0, 0, -9> look_at 0 angle 50 }
background { rgb <0.2, 0.8, 0.3> }
light_source { <0, 5, -100> rgb 1 }
#declare T = texture { pigment { rgbf <0.9, 0.1, 0.2, 0.8> } finish { reflection 1 } }
sphere { <-3.4, 0.8, 0>, 0.9 texture { T } }
sphere { <-2.4, 0.8, 0.5>, 0.9 texture { T } }
sphere { <-2.9, -1.6, 0>, 0.9 pigment { checker rgb 1 rgb 0 scale 0.3 } }
#for (I, 0, 4)
  box { <0.5 + I * 0.15, -2, -1 + I * 0.6>, <3.5 + I * 0.15, 2, -0.8 + I * 0.6>
        pigment { rgbf <1, 0.9, 0.8, 0.9> } }
#end
