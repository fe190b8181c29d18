// Iridescence with POV-Ray 3.7's default irid_wavelength (0.70, 0.52, 0.48), on lit
// surfaces, on what a reflection brings back (tinted before the reflection exponent) and
// on total internal reflection inside glass.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -8> look_at <0, 0.5, 0> angle 45 }
light_source { <-20, 30, -40> color rgb 0.9 }
sky_sphere { pigment { gradient y color_map { [0 rgb 0.1] [1 rgb <0.6, 0.8, 1>] } } }
plane { y, -1 pigment { checker rgb 0.9 rgb <0.2, 0.3, 0.6> } }
sphere { <-2, 0.2, 0>, 1 pigment { rgb 1 } finish { ambient 0 diffuse 0.3 irid { 0.5 thickness 2 turbulence 0.3 } } }
sphere { <0.3, 0.2, 0>, 1 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection { 0.6 } reflection_exponent 1.5 irid { 0.6 thickness 0.8 } } }
box { -1, 1 pigment { rgbf 1 } finish { diffuse 0 ambient 0 irid { 0.65 thickness 0.8 } }
      interior { ior 1.45 } scale <0.6, 1.2, 0.6> rotate <30, 40, 0> translate <2.4, 0.3, 0> }
