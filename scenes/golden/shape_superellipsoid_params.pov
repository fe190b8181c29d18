// superellipsoid: exponent pairs from rounded cubes (0.05, POV-Ray's stiffest example) to
// star-like shapes (e, n > 2, not convex), a scalar exponent, a non-uniform scale and one
// seen almost edge-on (grazing rays along its flat faces).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6, -10> look_at <0, 0.2, 0> angle 52 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 3, -5> color rgb 0.35 }
plane { y, -1.2 pigment { checker rgb 0.85 rgb 0.55 scale 0.8 } }
#declare F = finish { specular 0.5 roughness 0.02 }
superellipsoid { <0.05, 0.05> pigment { rgb <0.9, 0.4, 0.3> } finish { F }
                 scale 0.8 rotate <-20, 30, 0> translate <-3.2, 0, 2> }
superellipsoid { <0.25, 1> pigment { rgb <0.3, 0.8, 0.4> } finish { F }
                 scale 0.9 rotate <-70, 20, 0> translate <-1, 0, 2> }
superellipsoid { <1, 0.25> pigment { rgb <0.3, 0.5, 0.9> } finish { F }
                 scale 0.9 rotate <10, -40, 0> translate <1.2, 0, 2> }
superellipsoid { <2.5, 2.5> pigment { rgb <0.9, 0.8, 0.3> } finish { F }
                 scale 1.1 rotate <-30, 45, 0> translate <3.3, 0, 2> }
superellipsoid { 0.6 pigment { rgb <0.8, 0.4, 0.9> } finish { F }
                 scale <1.2, 0.5, 0.8> rotate <0, 25, 0> translate <-2.6, 0, -1> }
superellipsoid { <3, 0.3> pigment { rgb <0.4, 0.9, 0.9> } finish { F }
                 scale 0.9 rotate <60, 10, 30> translate <0, 0, -1.2> }
// Edge-on: the plane of its flat top passes 0.01 from the camera (grazing rays).
superellipsoid { <0.1, 0.15> pigment { rgb <0.9, 0.6, 0.2> } finish { F }
                 scale <0.9, 0.35, 0.9> rotate <31.82, 0, 0> translate <2.6, 0.3, -1.5> }
