// Object flags and less common items, each changing the image: no_image, no_reflection,
// no_shadow, double_illuminate, a light's looks_like, interior fade_colour,
// reflection_exponent, ramp_wave, composite (read as a union), alpha (read as filter), a
// deprecated identifier, sturm on a torus and an explicit perspective camera.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { perspective location <0, 2.5, -7> look_at <0, 0.4, 0> angle 50 }
light_source { <-3, 6, -4> color rgb 1 }
light_source { <2.5, 1.2, -1.5> color rgb <1, 0.8, 0.5>
               looks_like { sphere { 0, 0.15 pigment { rgb <1, 0.9, 0.3> } finish { ambient 1 } } } }
#declare deprecated Floor_colour = rgb <0.8, 0.8, 0.7>;
plane { y, -1 pigment { gradient x color_map { [0 Floor_colour] [1 rgb <0.2, 0.3, 0.6>] } ramp_wave }
        finish { reflection { 0.4 } reflection_exponent 2 } }
// Seen in the floor's reflection and casting its shadow, but not by the camera.
sphere { <-2.6, 0, 0.5>, 0.9 pigment { rgb <0.9, 0.2, 0.2> } no_image }
// Seen by the camera, missing from the reflection, casting no shadow.
sphere { <-0.6, 0, 0>, 0.8 pigment { rgb <0.2, 0.9, 0.3> } no_reflection no_shadow }
// A thin translucent leaf lit from behind.
box { <0.6, -1, 0.8>, <2.2, 0.8, 0.82> pigment { rgb <0.9, 0.9, 0.5> } double_illuminate }
composite {
  sphere { <1.4, -0.4, -1.2>, 0.5 }
  torus { 0.5, 0.15 rotate x * 60 translate <-1.6, -0.3, -2.2> sturm }
  pigment { color red 0.6 green 0.6 blue 1 alpha 0.6 }
  interior { ior 1.3 fade_distance 0.4 fade_power 2 fade_colour rgb <0.2, 0.4, 1> }
}
