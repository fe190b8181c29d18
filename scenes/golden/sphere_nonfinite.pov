// Spheres at a coordinate made by a division by zero (a spiral's first point at
// a / sqrt(0), a scale by 1/0): POV-Ray warns and goes on, and such a sphere is never
// hit. povwall read past its packed sphere arrays for them (found by a public-scene
// survey; the sanitizer build reports it).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at 0 }
light_source { <2, 5, -20> color rgb 1 }
plane { y, -1 pigment { rgb 0.8 } }
sphere { 0, 0.5 pigment { rgb <0, 0, 1> } }
sphere { 0, 0.2 pigment { rgb <1, 0, 0> } translate <1 / 0, 0, 0> }
#for (I, 0, 3)
  sphere { <1 / sqrt(I), 0, 0.3 * I>, 0.15 pigment { rgb <1, 0.6, 0> } }
#end
sphere { <-1, 0, 0>, 0.2 scale 1 / 0 pigment { rgb <0, 1, 0> } }
