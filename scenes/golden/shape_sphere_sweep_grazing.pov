// sphere_sweep seen grazing: a long linear tube and a B-spline lying almost in the
// camera's plane of view, rays skimming their envelopes; a sweep clipped by itself-sized
// boxes, a sheared one (matrix: distances and points through POV-Ray's matrix path), and
// an inverse one in an intersection.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.9, -8> look_at <0, 0.5, 0> angle 45 }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <4, 1, -6> color rgb 0.3 }
plane { y, -0.6 pigment { checker rgb 0.85 rgb 0.5 scale 0.5 } }
sphere_sweep { linear_spline 3, <-4, 0.3, 6>, 0.3, <-1, 0.3, -2>, 0.2, <1.5, 0.5, -4>, 0.05
               pigment { rgb <0.9, 0.5, 0.3> } }
sphere_sweep { b_spline 6, <-1, 0.35, 8>, 0.4, <0, 0.35, 4>, 0.3, <1, 0.35, 2>, 0.35,
               <2, 0.35, 0>, 0.25, <3, 0.35, -1>, 0.3, <4, 0.35, -2>, 0.2
               pigment { rgb <0.3, 0.6, 0.9> } finish { specular 0.5 } }
sphere_sweep { cubic_spline 6, <-1, 0, 0>, 0.3, <-0.5, 0.5, 0>, 0.3, <0, 0, 0.2>, 0.3,
               <0.5, 0.5, 0>, 0.3, <1, 0, 0>, 0.3, <1.5, 0.5, 0>, 0.3
               clipped_by { box { <-0.6, -1, -0.15>, <0.8, 1, 1> } }
               pigment { rgb <0.4, 0.9, 0.4> } matrix <1, 0, 0, 0.4, 1, 0, 0, 0, 1, 0, 0, 0>
               translate <-2.2, 1.4, 0> }
intersection {
  box { <-0.8, -0.5, -0.5>, <0.8, 0.5, 0.5> }
  sphere_sweep { linear_spline 3, <-1, 0, -0.6>, 0.25, <0, 0.2, 0.6>, 0.3, <1, 0, -0.6>, 0.25
                 inverse }
  pigment { rgb <0.9, 0.8, 0.4> } rotate <-30, 20, 0> translate <2.2, 1.4, 1> }
