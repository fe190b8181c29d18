// no_bump_scale and the slope pattern: POV-Ray's Perturb_Normal leaves the normal it
// perturbs for the patterns shaded after it (PNormal) before Trace normalises it, so with
// the flag the slope pattern reads a normal that is not unit length. Left: a texture_map
// whose upper entry has the flag (its lower entry's slope reads its bumps); middle: the
// flag on the texture_map (its pattern's space and its entries), the sphere squashed;
// right: layers, the bumped bottom layer has the flag and the top layer's slope reads it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 40 }
light_source { <-5, 10, -10>, rgb 1 }
background { rgb <0.2, 0.3, 0.4> }

#declare Bumpy = texture {
    pigment { rgb 0.6 }
    normal { bumps 0.5 scale 0.1 }
    scale 0.5
    no_bump_scale
}
#declare BySlope = texture {
    pigment { slope y color_map { [0 rgb <1, 0.1, 0>] [1 rgb <0, 0.4, 1>] } }
}

sphere { <-2.2, 0, 0>, 1
    texture { gradient x translate -0.5 * x scale 2 translate -2.2 * x
        texture_map { [0 BySlope] [1 Bumpy] } }
}
sphere { <0, 0, 0>, 1
    texture { gradient x translate -0.5 * x scale 2
        texture_map { [0 BySlope] [1 Bumpy] } no_bump_scale }
    scale <1.2, 0.8, 1>
}
sphere { <2.2, 0, 0>, 1
    texture { pigment { rgb 0.3 } normal { bumps 0.4 scale 0.2 no_bump_scale } }
    texture {
        pigment { slope y color_map { [0 rgbt <1, 0.1, 0, 0.5>] [1 rgbt <0, 0.4, 1, 0.5>] } }
    }
}
