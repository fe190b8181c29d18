// POV-Ray keeps no sphere hit at or past MAX_DISTANCE (1e7) along a unit direction in
// the sphere's own space (Sphere::All_Intersections): a sphere squashed by 1e-7 is met
// ~1e8 units deep in its own space and vanishes, one squashed by 1e-5 stays; a sphere
// around the camera with a radius of 2e7 is not seen (its far side is too deep), one of
// 5e6 is. Plain, in CSG and as a shadow caster.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at 0 angle 40 }
light_source { <-300, 3000, -500> rgb 1 }
background { rgb <0.1, 0.2, 0.4> }
sphere { 0, 1 scale <1, 1e-7, 1> rotate <-30, 0, 75> translate <-2, 1, 0> pigment { rgb 1 } }
sphere { 0, 1 scale <1, 1e-5, 1> rotate <-30, 0, 75> translate <2, 1, 0> pigment { rgb <1, 0.5, 0.2> } }
intersection {
  sphere { 0, 1 scale <1, 1e-7, 1> rotate <-30, 0, 75> }
  box { -2, 2 }
  translate <-2, -1.5, 0> pigment { rgb <0.2, 1, 0.4> }
}
union {
  sphere { 0, 1 scale <1, 1e-5, 1> rotate <-30, 0, 75> }
  sphere { <0, -0.6, 0>, 0.3 }
  translate <2, -1.5, 0> pigment { rgb <0.7, 0.7, 1> }
}
sphere { 0, 2e7 hollow pigment { rgb <1, 0, 0> } }
sphere { <0, 0, 100>, 5e6 hollow pigment { checker rgb 0.3 rgb 0.6 scale 1e5 } finish { ambient 1 diffuse 0 } }
plane { y, -3 pigment { rgb 0.8 } }
