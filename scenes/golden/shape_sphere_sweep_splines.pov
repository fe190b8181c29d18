// sphere_sweep: each spline kind with varying radii (the templates' 7A-7C curves), a
// tight bend, a Catmull-Rom whose curve leaves its box, transforms moved into the
// spheres (translate, rotate, uniform and negative scale) and kept as a matrix
// (non-uniform scale), and a linear sweep seen along its axis.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -11> look_at <0, 0.6, 0> angle 55 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 3, -5> color rgb 0.35 }
plane { y, -1.5 pigment { checker rgb 0.85 rgb 0.55 scale 0.8 } }
#declare F = finish { specular 0.5 roughness 0.02 }
sphere_sweep { linear_spline 4, <-1, 0, 0>, 0.25, <0, 1, 0>, 0.15, <1, 0, 0>, 0.35,
               <1.5, 0.8, -0.5>, 0.1
               pigment { rgb <0.9, 0.4, 0.3> } finish { F } translate <-3.5, 1.8, 1> }
sphere_sweep { cubic_spline 6, <-1.5, -0.5, 0>, 0.2, <-1, 0, 0>, 0.2, <0, 1, 0.3>, 0.35,
               <1, 0, -0.3>, 0.15, <1.5, 0.5, 0>, 0.25, <2, 0, 0>, 0.2
               pigment { rgb <0.3, 0.8, 0.4> } finish { F } rotate <-20, 30, 0>
               translate <0, 1.8, 1> }
sphere_sweep { b_spline 6, <-1.5, -0.5, 0>, 0.35, <-1, 0, 0>, 0.3, <0, 1, 0.3>, 0.25,
               <1, 0, -0.3>, 0.2, <1.5, 0.5, 0>, 0.15, <2, 0, 0>, 0.1 tolerance 0.001
               pigment { rgb <0.3, 0.5, 0.9> } finish { F } scale 1.2 translate <3.3, 1.5, 1> }
// A hairpin: the linear tube folds back within its radius.
sphere_sweep { linear_spline 3, <-1, 0, 0>, 0.3, <1, 0, 0>, 0.3, <-1, 0.35, 0>, 0.25
               pigment { rgb <0.9, 0.8, 0.3> } finish { F } rotate <0, -20, 0>
               translate <-3.5, -0.8, 0> }
// A Catmull-Rom with small radii overshooting its +-2r box, then a non-uniform scale.
sphere_sweep { cubic_spline 5, <-1, -1, 0>, 0.05, <-0.5, 0.6, 0>, 0.1, <0.5, 0.6, 0>, 0.1,
               <1, -1, 0>, 0.05, <1.5, 1, 0>, 0.05
               pigment { rgb <0.8, 0.3, 0.8> } finish { F } scale <1.4, 1, 1>
               translate <0, -0.6, -1> }
// A tight cubic bend, scaled by -1 (negative radii) and moved.
sphere_sweep { b_spline 5, <-1, 0, 0>, 0.3, <1, 0, 0>, 0.3, <1, 0.8, 0>, 0.3, <-1, 0.8, 0>, 0.3,
               <-0.5, -0.3, 0>, 0.2
               pigment { rgb <0.4, 0.9, 0.9> } finish { F } scale -1 rotate <0, 30, 0>
               translate <3, -0.6, 0> }
// Seen almost along its axis: the envelope's grazing and perpendicular rays.
sphere_sweep { linear_spline 2, <0, 0, 0>, 0.2, <0, 0, 4>, 0.4
               pigment { rgb <1, 0.6, 0.2> } finish { F } translate <1.2, 0.2, -6> }
