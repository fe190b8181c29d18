// Which objects a camera ray starts inside, as POV-Ray 3.7 decides it: the camera must be
// in the object's own bounding box and inside the object by its own test, its clips not
// asked. An inverted glass cone keeps its finite box, so a camera outside that box starts
// in air (and the fog applies); a camera inside a glass sphere, in the half its clip
// removes, starts in the glass (no fog: a non-hollow interior, refraction at the rest);
// an inverted CSG keeps its box as an inverted shape does.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.5, -1> look_at <0, 0, 5> angle 70 }
light_source { <5, 10, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
fog { distance 9 rgb <0.8, 0.75, 0.9> }
sphere { 0, 3 clipped_by { plane { y, 0 } }
         pigment { rgbf <1, 0.9, 0.9, 0.9> } interior { ior 1.3 } }
cone { <-0.8, -0.8, -0.7>, 0.23, <0.6, 0.7, 0.7>, 0.17 inverse
       pigment { rgbt <0.9, 1, 0.9, 0.8> } interior { ior 1.64 } translate <1.5, 0, 5> }
sphere { <-1, 0, 5>, 1 pigment { checker rgb 1 rgb <1, 0, 0> scale 0.3 } }
plane { y, -3 pigment { checker rgb 1 rgb 0.2 } }
// An inverted union keeps the finite box it was built with: the camera is outside it, so
// outside the union though it lies outside both spheres (the fog still applies).
union { sphere { <2.5, -2, 8>, 0.6 } sphere { <3.3, -2, 8>, 0.5 } inverse
        pigment { rgbf <1, 0.9, 0.8, 0.5> } interior { ior 1.2 } }
