// A julia_fractal's inverse flag in POV-Ray 3.7: its own set-up clears it (`inverse` in its
// block does nothing), `object { Julia inverse }` keeps it, and every transform after it clears
// it again, whichever way it was inverted: by its own flag, by an inverse CSG around it or as a
// difference's later part (Fractal::Transform recomputes its box, which resets the flag).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -9> look_at <0, 0, 0> angle 52 }
light_source { <5, 10, -10> rgb 1 }
light_source { <-6, 3, -4> rgb 0.4 }
#declare J = julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15 }
#declare P = prism { linear_sweep linear_spline -0.4, 0.6, 6, <0.9, 0>, <0.27, 0.81>, <-0.72, 0.54>, <-0.63, -0.63>, <0.36, -0.81>, <0.9, 0> }
// merge of the inverted julia and the inverted prism: no transform after, so both stay inverted
merge { object { J inverse } object { P inverse } pigment { rgb <0.6, 0.4, 0.8> } translate <-3, 1.3, 0> }
// inverse intersection, then a rotation: the julia is no longer inverted, the prism is
intersection { object { J } object { P } inverse pigment { rgb <0.4, 0.7, 0.5> } rotate <20, 30, 10> translate <0, 1.3, 0> }
// the same without the rotation: both inverted (what shows is the intersection's surface)
intersection { object { J } object { P } inverse pigment { rgb <0.8, 0.6, 0.3> } translate <3, 1.3, 0> }
// a difference whose julia part is moved after it was subtracted: the julia is intersected
difference { object { P scale 1.2 } object { J } rotate y * 40 pigment { rgb <0.5, 0.6, 0.9> } translate <-3, -1.5, 0> }
// the julia subtracted, not moved after: it is cut out
difference { object { P scale 1.2 } object { J } pigment { rgb <0.9, 0.5, 0.5> } translate <0, -1.5, 0> }
// inverse in the julia's own block: cleared by its set-up
intersection { julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15 inverse } object { P } pigment { rgb <0.7, 0.7, 0.7> } translate <3, -1.5, 0> }
plane { y, -3 pigment { checker rgb 0.9 rgb 0.6 } }
