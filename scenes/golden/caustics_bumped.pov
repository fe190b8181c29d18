// Faked caustics under a bumped water surface written as `plane { y, 10 }` (its normal
// points up, toward the light above it) and as `plane { -y, -10.5 }`: POV-Ray turns the normal to face the
// shadow ray before perturbing it, then brightens by the perturbed angle.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { angle 65 location <0, 6, -15> right x * 4/3 look_at 0 }
light_source { <0, 50, 0> color rgb 1 }
plane { y, 0 pigment { rgb 0.6 } finish { ambient 0 diffuse 0.7 } }
plane { y, 10 hollow pigment { rgbf 1 } interior { ior 1.1 caustics 1 } normal { bumps 0.5 } }
plane { -y, -10.5 hollow pigment { rgbf 1 } interior { ior 1.1 caustics 0.7 } normal { bumps 0.3 scale 2 }
        clipped_by { box { <0, 9, -100>, <100, 11, 100> } } }
sphere { <-2, 1, 0>, 1 pigment { rgb <0.9, 0.5, 0.3> } }
