// lathe: each spline kind on the outline of objects/lathe1*.pov, a Bezier bulb, sturm on
// the quartic, a negative end radius (POV-Ray's squared bounding radii hide part of it),
// and one seen edge-on from the plane of a flat linear annulus.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -11> look_at <0, 0.5, 0> angle 55 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 3, -5> color rgb 0.35 }
plane { y, -1.5 pigment { checker rgb 0.85 rgb 0.55 scale 0.8 } }
#declare F = finish { specular 0.5 roughness 0.02 }
lathe { linear_spline 12, <2, 1>, <2, -1>, <3, -1>, <3.4, -2>, <4, -1.1>, <3.6, -0.9>,
        <2.6, 0>, <3.6, 0.9>, <4, 1.1>, <3.4, 2>, <3, 1>, <2, 1>
        pigment { rgb <0.9, 0.4, 0.3> } finish { F } scale 0.35 rotate <-30, 0, 0>
        translate <-3.8, 0, 2> }
lathe { quadratic_spline 13, <2, 1>, <2, -1>, <3, -1>, <3.4, -2>, <4, -1.1>, <3.6, -0.9>,
        <2.6, 0>, <3.6, 0.9>, <4, 1.1>, <3.4, 2>, <3, 1>, <2, 1>, <2, -1>
        pigment { rgb <0.3, 0.8, 0.4> } finish { F } scale 0.35 rotate <-60, 0, 10>
        translate <-1.2, 0.3, 2> }
lathe { cubic_spline 14, <2, 1>, <2, -1>, <3, -1>, <3.4, -2>, <4, -1.1>, <3.6, -0.9>,
        <2.6, 0>, <3.6, 0.9>, <4, 1.1>, <3.4, 2>, <3, 1>, <2, 1>, <2, -1>, <3, -1>
        pigment { rgb <0.3, 0.5, 0.9> } finish { F } scale 0.35 rotate <-20, 0, -20>
        translate <1.4, 0.3, 2> }
lathe { quadratic_spline 5, <0, 0>, <1, 0>, <0.8, 1>, <0.2, 1.6>, <0, 2> sturm
        pigment { rgb <0.9, 0.8, 0.3> } finish { F } translate <3.8, -1.2, 2> }
lathe { bezier_spline 8, <0, 0>, <1.2, 0>, <1, 0.8>, <0.5, 1>, <0.5, 1>, <0.1, 1.2>,
        <0.6, 1.8>, <0, 2> sturm
        pigment { rgb <0.8, 0.4, 0.9> } finish { F } rotate <0, 0, 40> translate <-3.2, -1, -1.5> }
// A negative first radius: the bounding cylinders' squared radii skip its inner part.
lathe { linear_spline 3, <-0.6, 0>, <1, 0.5>, <0.3, 1.5>
        pigment { rgb <0.4, 0.9, 0.9> } finish { F } rotate <-40, 0, 0> translate <0, -0.6, -1.5> }
// Edge-on: the flat annulus (a horizontal linear segment) 0.01 below the camera.
lathe { linear_spline 5, <0.3, 0>, <1.2, 0>, <1.2, 0.3>, <0.6, 0.3>, <0.3, 0>
        pigment { rgb <0.9, 0.6, 0.2> } finish { F } translate <2.8, 4.69, -1.5> }
