// The signed cosine of angle-dependent reflection seen from below: on the left the camera
// is inside a bumped water box (fresnel with ior 1.33 relative 1/1.33 from inside, total
// internal reflection where the bumps turn the surface), on the right under a bumped
// ceiling slab with variable reflection (falloff 1 and 3), all at grazing angles where
// the perturbed normal faces away from the ray.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, -1.5, -10> look_at <0, 0, 0> angle 70 }
light_source { <-20, 300, -40> color rgb 1 }
light_source { <0, -5, -12> color rgb 0.5 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.9, 1>] [1 rgb <0.1, 0.2, 0.8>] } } }
box { <-60, -9, -30>, <0, 0, 60>
      texture { pigment { rgbf <0.7, 0.9, 1, 0.8> }
                finish { ambient 0 diffuse 0.1 reflection { 0, 1 fresnel on } }
                normal { bumps 0.7 scale 1.5 } }
      interior { ior 1.33 } }
box { <0, 0, -30>, <60, 0.3, 60>
      texture { pigment { rgb <0.7, 0.3, 0.2> } finish { ambient 0.2 diffuse 0.3 reflection { 0, 1 } }
                normal { wrinkles 0.8 scale 1.2 } } }
box { <0, -9, 5>, <60, -8.5, 60>
      texture { pigment { rgb <0.2, 0.3, 0.7> } finish { ambient 0.2 diffuse 0.3 reflection { 0.1, 0.8 falloff 3 } }
                normal { bumps 1 scale 1 } } }
plane { y, -9.5 pigment { checker rgb 0.9 rgb <0.1, 0.3, 0.6> scale 2 } finish { ambient 0.3 } }
sphere { <-3, 3, 10>, 2 pigment { rgb <0.9, 0.2, 0.2> } }
