// Sphere sweeps whose polynomials are stiff: a linear sweep folding back on itself, a
// B-spline hairpin tighter than its radius, radii near zero (a cone to a point), repeated
// control points (zero-length segments, duplicated Catmull-Rom ends as exporters write),
// tiny and huge.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.6, -9> look_at <0, 0.3, 0> angle 45 }
light_source { <10, 20, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
sphere_sweep { linear_spline 4, <-1, 0, 0>, 0.3, <1, 0, 0>, 0.3, <-1, 0.2, 0>, 0.3,
               <1, 0.4, 0>, 0.3
               pigment { rgb 1 } rotate <10, 20, 0> translate <-2.6, 1.4, 0> }
sphere_sweep { b_spline 6, <-1, 0, 0>, 0.3, <1, 0, 0>, 0.3, <1, 0.2, 0>, 0.3,
               <-1, 0.2, 0>, 0.3, <-1, 0.4, 0>, 0.3, <1, 0.4, 0>, 0.3
               pigment { rgb <1, 0.6, 0.2> } translate <0, 1.4, 0> }
sphere_sweep { linear_spline 3, <0, -1, 0>, 0.5, <0, 0.5, 0>, 1e-6, <0, 0.5, 0>, 1e-6
               pigment { rgb <0.6, 1, 0.2> } rotate <0, 0, 30> translate <2.6, 1, 0> }
sphere_sweep { cubic_spline 5, <-1, 0, 0>, 0.2, <-1, 0, 0>, 0.2, <0, 0.5, 0>, 0.3,
               <1, 0, 0>, 0.2, <1, 0, 0>, 0.2
               pigment { rgb 0.7 } translate <-2.4, -1, 0> }
sphere_sweep { linear_spline 2, <0, 0, 0>, 0.5, <0, 1, 0>, 0.5
               pigment { rgb 0.5 } scale 1e-3 translate <0, 0.55, -8.99> }
sphere_sweep { b_spline 4, <0, 0, 0>, 1, <1, 2, 0>, 0.5, <2, 0, 1>, 1, <3, 1, 0>, 0.5
               pigment { rgb <0.4, 0.6, 1> } scale <1e3, 1e3, 2e3> translate <2e3, -2.4e3, 6e3> }
