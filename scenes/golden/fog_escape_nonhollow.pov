// Fog only where the ray is in hollow space (POV-Ray's TraceRay fogs a ray only when every
// interior it is inside of is hollow): rays through a transparent solid plane, disc or
// triangle that escape to the sky while inside it show the sky unfogged; under the hollow
// plane they are fogged; a hollow sphere under the solid plane keeps them unfogged, a
// solid sphere under the hollow plane unfogs the rays that end inside it (nested
// interiors), and leaving a solid object brings the fog back.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 6, -14> look_at <0, 0, 0> angle 70 }
light_source { <-20, 300, -40> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.9, 1>] [1 rgb <0.1, 0.2, 0.8>] } } }
fog { fog_type 1 distance 20 color rgb <0.8, 0.5, 0.3> }
// Solid (the default), hollow, and explicitly not hollow.
plane { y, 0 pigment { rgbt <0.2, 0.7, 0.3, 0.6> } finish { ambient 0.3 diffuse 0 } clipped_by { box { <-30, -1, -30>, <-3, 1, 60> } } }
plane { y, 0 hollow pigment { rgbt <0.2, 0.7, 0.3, 0.6> } finish { ambient 0.3 diffuse 0 } clipped_by { box { <-3, -1, -30>, <3, 1, 60> } } }
plane { y, 0 hollow off pigment { rgbt <0.2, 0.7, 0.3, 0.6> } finish { ambient 0.3 diffuse 0 } interior { ior 1.2 } clipped_by { box { <3, -1, -30>, <30, 1, 60> } } }
// Nested: a hollow glass sphere under the solid plane, a solid one under the hollow plane.
sphere { <-6, -3, 2>, 2.5 hollow pigment { rgbt <1, 1, 1, 0.8> } finish { ambient 0.2 diffuse 0.2 } }
sphere { <0, -3, 2>, 2.5 pigment { rgbt <1, 1, 1, 0.8> } finish { ambient 0.2 diffuse 0.2 } }
// A closed solid box above the planes: fog again after the ray leaves it.
box { <4, 1, -2>, <8, 4, 1> pigment { rgbt <0.9, 0.9, 1, 0.8> } finish { ambient 0.1 diffuse 0.2 } }
// Open surfaces: a transparent disc and triangle leave the ray "inside" them.
disc { <-5, 4, 3>, <0.3, 0, -1>, 2.5 pigment { rgbt <1, 0.8, 0.8, 0.7> } finish { ambient 0.2 diffuse 0 } }
triangle { <-1, 2.5, 4>, <3, 2.5, 4>, <1, 6, 5> pigment { rgbt <0.8, 0.8, 1, 0.7> } finish { ambient 0.2 diffuse 0 } }
