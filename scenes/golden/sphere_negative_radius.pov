// A sphere with a negative radius: POV-Ray squares the radius for the surface, but its
// own bounding box (centre - radius, length 2 radius) is inverted, so its slab tree never
// enters it: plain, rotated or uniformly scaled, the sphere is not seen. A transform the
// sphere keeps (a non-uniform scale, a matrix) recomputes the box from the transformed
// corners, which makes it valid: that ellipsoid shows (found by a public-scene survey).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -6> look_at 0 }
light_source { <-5, 10, -10> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.5 } }
sphere { <0, 0, 0>, -1 pigment { rgb <1, 0, 0> } }
sphere { <1.5, 0, 0>, -0.5 scale 2 rotate 30 * y pigment { rgb <0, 1, 0> } }
sphere { <-1.2, 0, 0>, -0.5 scale <2, 1, 1> pigment { rgb <0, 0, 1> } }
sphere { <0, 1.2, 0>, -0.4 scale <1, 2, 1> rotate 20 * z pigment { rgb <1, 1, 0> } }
sphere { <1.5, -0.5, 1>, -0.5 matrix <1, 0, 0, 0.3, 1, 0, 0, 0, 1, 0, 0, 0>
         pigment { rgb <1, 0, 1> } }
