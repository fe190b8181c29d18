// Reflection and refraction where a strong normal pattern tilts the surface normal past
// the ray (POV-Ray's ComputeReflection: mirrored again about the true normal, or about it
// alone), refraction bent about the normal turned to face the ray, and total internal
// reflection under a bumped water surface seen from below, reflected the same way.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 1.2, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.3, 0.1>] [0.1 rgb <0.9, 0.3, 0.1>]
                                             [0.1 rgb <0.2, 0.8, 0.3>] [0.3 rgb <0.2, 0.8, 0.3>]
                                             [0.3 rgb <0.2, 0.3, 0.9>] [1 rgb <0.2, 0.3, 0.9>] } } }
// A mirror floor with a steep gradient normal and one with bumps.
plane { y, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 }
        normal { gradient x, 3 scale 0.7 } clipped_by { box { <-6, -1, -2>, <0, 1, 8> } } }
plane { y, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 }
        normal { bumps 0.6 scale 0.2 } clipped_by { box { <0, -1, -2>, <6, 1, 8> } } }
// Glass with a normal pattern that turns the normal away from some rays.
box { <-3, 0.5, -1>, <-0.5, 3, -0.8> pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
      normal { gradient x, -4 scale 0.6 } interior { ior 1.33 } }
// A water layer seen from below: total internal reflection off a bumped surface.
box { <0.5, 0.3, -1>, <3.5, 3, 1> hollow pigment { rgbf 1 } finish { ambient 0 diffuse 0 reflection 0.3 }
      normal { bumps 0.5 scale 0.3 } interior { ior 1.1 } }
sphere { <2, 1.2, 0>, 0.5 pigment { checker rgb 1 rgb <0.6, 0.1, 0.1> scale 0.25 } }
