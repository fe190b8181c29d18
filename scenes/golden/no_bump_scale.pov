// no_bump_scale (POV-Ray 3.7's DONT_SCALE_BUMPS_FLAG): the normal goes into the normal
// pattern's space and back without being renormalised, so the pattern's, texture's and
// object's scaling change the bumps' slopes (scaled down: steeper, non-uniformly: tilted
// unevenly); POV-Ray's Trace normalises after the perturbation. Written in the normal or
// in the texture (after its transforms; handed to the normal, to a texture_map's
// pattern and its entries, not to the other layers).
// Top row: the same bumps without the flag, in the normal, in the texture; a box scaled
// non-uniformly with ripples and the texture's flag. Bottom row: that box without it; a
// normal_map with the flag on a squashed sphere; a texture_map given the flag; layered
// textures with the flag on the top layer only. Floor: waves, the texture's flag.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -12> look_at <0, 0, 0> angle 42 }
light_source { <-6, 10, -12>, rgb 1 }
light_source { <8, 4, -6>, rgb 0.3 }
background { rgb <0.2, 0.25, 0.3> }

#declare Tan = pigment { rgb <0.8, 0.7, 0.5> }
#declare Bumpy = normal { bumps 0.4 scale 0.3 }

sphere { 0, 1 texture { pigment { Tan } normal { Bumpy } } scale 0.8 translate <-3.3, 1.2, 0> }
sphere { 0, 1 texture { pigment { Tan } normal { Bumpy no_bump_scale } } scale 0.8
    translate <-1.1, 1.2, 0> }
sphere { 0, 1 texture { pigment { Tan } normal { Bumpy } scale 2 no_bump_scale } scale 0.8
    translate <1.1, 1.2, 0> }
box { -1, 1
    texture { pigment { rgb <0.5, 0.7, 0.9> } normal { ripples 0.8 scale 0.4 } no_bump_scale }
    scale <0.9, 0.35, 0.6> rotate <-30, 35, 0> translate <3.3, 1.2, 0> }

box { -1, 1
    texture { pigment { rgb <0.5, 0.7, 0.9> } normal { ripples 0.8 scale 0.4 } }
    scale <0.9, 0.35, 0.6> rotate <-30, 35, 0> translate <-3.3, -1.1, 0> }
sphere { 0, 1
    texture { pigment { rgb <0.9, 0.6, 0.6> }
        normal { gradient x normal_map { [0 bumps 0.6 scale 0.2] [1 wrinkles 0.5 scale 0.3] }
            scale 0.7 no_bump_scale } }
    scale <0.9, 0.55, 0.9> translate <-1.1, -1.1, 0> }
#declare Smooth = texture { pigment { rgb <0.6, 0.9, 0.6> } }
#declare Dented = texture { pigment { rgb <0.9, 0.9, 0.5> } normal { dents 1.5 scale 0.25 } }
sphere { 0, 1
    texture { gradient x texture_map { [0.3 Dented] [0.7 Smooth] } translate -0.5 * x scale 2
        no_bump_scale }
    scale 0.8 translate <1.1, -1.1, 0> }
sphere { 0, 1
    texture { pigment { rgb <0.7, 0.5, 0.9> } normal { bumps 0.5 scale 0.15 } }
    texture { pigment { rgbt <1, 1, 1, 0.6> } normal { ripples 0.6 scale 0.2 } no_bump_scale }
    scale <1.1, 0.7, 0.7> translate <3.3, -1.1, 0> }

plane { y, -2
    texture { pigment { checker rgb 0.75 rgb 0.5 scale 1.5 }
        normal { waves 1.2 } scale 1.5 no_bump_scale } }
