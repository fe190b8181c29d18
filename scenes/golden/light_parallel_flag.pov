// parallel is a flag of its own, whatever its place: a parallel spotlight (parallel
// before spotlight) lights everything from point_at's direction at full strength.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.3, 0> angle 45 }
light_source { <-4, 6, -5> color rgb 1 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1, 0.3, 0.6> scale 0.5 } }
light_source { <3, 5, -2> color rgb <0.6, 0.5, 0.3> parallel spotlight point_at <0, 0, 0> radius 5 falloff 10 }
light_source { <-3, 4, 2> color rgb <0.2, 0.3, 0.6> spotlight parallel point_at <0, 0, 0> }
sphere { <0, 0.2, 0>, 1 pigment { rgb <1, 0.5, 0.2> } }
