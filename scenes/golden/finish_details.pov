// Finish details POV-Ray applies: diffuse back (light from behind a thin panel, without
// highlights), albedo applied when the finish block ends (with the brilliance, phong_size
// and roughness written after it), specular albedo, and thin-film iridescence with
// turbulence and irid_wavelength.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.3, 0> angle 45 }
light_source { <-4, 6, -5> color rgb 1 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1, 0.3, 0.6> scale 0.5 } }
global_settings { irid_wavelength rgb <0.3, 0.2, 0.15> }
light_source { <0, 0.5, 5> color rgb 0.7 }
box { <-2.2, -1, 1>, <2.2, 1.6, 1.05> pigment { rgb <0.9, 0.8, 0.3> } finish { diffuse 0.5, 0.4 phong 0.9 } }
sphere { <-1.2, 0, -0.5>, 0.55 pigment { rgb <1, 0.5, 0.2> } finish { diffuse albedo 0.6 brilliance 3 phong albedo 0.5 phong_size 10 } }
sphere { <0, 0, -0.5>, 0.55 pigment { rgb <0.2, 0.5, 1> } finish { specular albedo 0.6 roughness 0.02 } }
sphere { <1.2, 0, -0.5>, 0.55 pigment { rgb 0.8 } finish { irid { 0.4 thickness 0.3 turbulence 0.5 } } }
