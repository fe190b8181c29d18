// Atmospheric media (a scene-level media block): absorption and emission on every ray,
// inside a hollow glass sphere too, not inside a solid one; a hollow sky sphere encloses
// the view (rays that miss everything: media_atmosphere_sky.pov).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 0.8, 0> angle 50 }
light_source { <-3, 6, -5> color rgb 1 }
media { absorption 0.08 emission 0.02 }
sphere { 0, 40 hollow pigment { rgb <0.3, 0.5, 0.9> } finish { emission 1 diffuse 0 } }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
sphere { <-1.2, 1, 0>, 0.9 hollow pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.3 } }
sphere { <1.2, 1, 0>, 0.9 pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.3 } }
box { <-3, 0, 4>, <3, 2.5, 4.5> pigment { rgb <0.8, 0.3, 0.2> } }
