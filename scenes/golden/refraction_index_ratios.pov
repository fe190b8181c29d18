// The ratio of refractive indices at a surface, in POV-Ray's precision: entering from the
// atmosphere POV-Ray divides its double atmosphereIOR by the float ior (1 / 1.4 in double,
// not in float), between two objects it divides float by float, in refraction and in
// fresnel reflection alike. A sky that changes every 1e-7 of a direction shows a ray bent
// by the last bits of the ratio (a survey scene's star field through glass spheres).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
sky_sphere { pigment { function { abs(x * 1e7 + y * 3e6) - floor(abs(x * 1e7 + y * 3e6)) } } }
camera { location <0, 0.3, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 5, -6> rgb 1 }
// Entering from the atmosphere (a slab), with dispersion's ratio too.
box { <-2.6, -1.6, -0.1>, <-0.9, 1.6, 0.1> pigment { rgbf <1, 1, 1, 1> }
  interior { ior 1.4 dispersion 1.02 dispersion_samples 3 } }
// A sphere inside a box: entering and leaving one object while inside another, with
// fresnel reflection at each surface.
box { <-0.6, -1.4, -1>, <2.6, 1.4, 1> pigment { rgbf <1, 1, 1, 1> }
  finish { reflection { 0, 1 fresnel on } conserve_energy }
  interior { ior 1.5 } }
sphere { <1, 0, 0>, 0.8 pigment { rgbf <1, 1, 1, 1> }
  finish { reflection { 0, 1 fresnel on } conserve_energy }
  interior { ior 1.33 } }
