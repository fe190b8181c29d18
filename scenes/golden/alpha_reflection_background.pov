// golden-args: +UA
// With +UA only camera rays and what they transmit see the background as transparent: a
// reflected ray (and every ray under it) sees its colour, whole (POV-Ray clears the
// ticket's alphaBackground in ComputeReflection), as ASE writes its scenes
// (background { White transmit 1.0 } with Output_Alpha=on).
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.9, 0.8, 0.6> transmit 1.0 }
camera { orthographic right -4 * x up 3 * y location <0, 0, 50> look_at <0, 0, 0> }
light_source { <2, 3, 40> color rgb 1 }
sphere { <-1, 0.4, 0>, 0.9 pigment { color rgb <0.2, 0.3, 0.8> } finish { ambient 0.1 diffuse 0.5 reflection 0.5 } }
sphere { <1, 0.4, 0>, 0.9 pigment { color rgbt <0.8, 0.3, 0.2, 0.4> } finish { reflection 0.3 phong 0.6 } }
// Glass: refracted rays see the transparent background, reflected ones its colour; the
// pixels brighter than their little alpha take their brightness as alpha in the PNG
// (output/image_io.cpp, as POV-Ray writes straight alpha).
sphere { <0, -0.9, 0>, 0.6 pigment { color rgbf <0.9, 1, 0.9, 0.9> } finish { reflection { 0.1 0.6 fresnel } } interior { ior 1.5 } }
