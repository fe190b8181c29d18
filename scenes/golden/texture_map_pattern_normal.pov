// POV-Ray 3.7 keeps one pattern normal per hit (the normal facing the ray, then each
// layer's perturbed normal: Perturb_Normal stores it, the slope pattern reads it), and
// a texture_map shades its upper entry before its lower one: the lower entry's patterns
// see the bumps of the upper. Left: the slope pigment is the lower entry, mottled by
// the bumps of the upper; middle: the entries swapped, the slope is smooth; right: as
// textures/patterns/slopemt.pov's mountain, a gradient map whose entries are the same
// slope map with a bumped entry (its lower entry's slope reads the bumps its upper one
// left).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 40 }
light_source { <-5, 10, -10>, rgb 1 }
background { rgb <0.2, 0.3, 0.4> }

#declare Bumpy = texture { pigment { rgb 0.6 } normal { bumps 2 scale 0.1 } }
#declare BySlope = texture {
    pigment { slope y color_map { [0 rgb <1, 0.1, 0>] [1 rgb <0, 0.4, 1>] } }
}
#declare SlopeMap = texture {
    slope { -y } texture_map { [0.3 Bumpy] [0.5 BySlope] }
}

sphere { <-2.2, 0, 0>, 1
    texture { gradient x translate -0.5 * x scale 2 translate -2.2 * x
        texture_map { [0 BySlope] [1 Bumpy] } }
}
sphere { <0, 0, 0>, 1
    texture { gradient x translate -0.5 * x scale 2
        texture_map { [0 Bumpy] [1 BySlope] } }
}
sphere { <2.2, 0, 0>, 1
    texture { gradient x translate -0.5 * x scale 2 translate 2.2 * x
        texture_map { [0 SlopeMap] [1 SlopeMap] } }
}
