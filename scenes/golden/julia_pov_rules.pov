// Two of POV-Ray's julia_fractal rules. Its set-up at each transform clears the inverted
// flag, so a julia a difference subtracted is intersected once the difference (or an
// object around it) is moved; a julia moved only in its own braces stays subtracted.
// Outside CSG it reports its first hit only, and a shadow ray POV-Ray restarts past a
// see-through surface marches afresh: a clear julia filters the light at its entry and
// again at its exit.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -6> look_at <0, 0, 0> angle 55 }
light_source { <2, 6, -4> rgb 1 }
background { rgb <0.3, 0.4, 0.6> }
plane { y, -1 pigment { rgb 1 } }
#declare J = julia_fractal { <-0.279, 0.026, -0.002, 0.063> hypercomplex sqr
  max_iteration 5 precision 20 }
// Subtracted, then the difference turned: intersected.
difference { box { -0.8, 0.8 pigment { rgb 1 } } object { J scale 0.8 }
  pigment { rgb <0.3, 0.8, 0.3> } rotate <20, 30, 0> translate <-2.2, 0, 0> }
// Subtracted and moved only inside: still subtracted.
difference { box { -0.8, 0.8 } object { J scale 0.8 rotate <20, 30, 0> }
  pigment { rgb <0.9, 0.6, 0.3> } rotate <20, 30, 0> translate <0, 0, 1> }
// A clear julia standing on the floor: its shadow is filtered twice.
object { J scale 0.9 pigment { rgbt <1, 0.7, 0.5, 0.5> } translate <2.2, 0, 0> }
