// Objects exactly on the virtual walls of --boxes 2x2x2 (the scene bounds are symmetric, so the
// middle walls are x = 0, y = 0, z = 0) and on octree cell planes: faces at 0, spheres centred
// on a wall, a plane through a wall.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <2.5, 3, -6> look_at <0, 0, 0> }
light_source { <10, 15, -10> rgb 1 }
background { rgb <0.3, 0.3, 0.35> }
box { <-2, -2, -2>, <0, 0, 0> pigment { rgb <1, 0.3, 0.3> } }
box { <0, 0, 0>, <2, 2, 2> pigment { rgb <0.3, 1, 0.3> } }
sphere { <0, 1, -1>, 0.5 pigment { rgb <0.3, 0.3, 1> } }
sphere { <0, 0, 0>, 0.25 pigment { rgb 1 } }
cylinder { <-2, 0, -1.5>, <2, 0, -1.5>, 0.2 pigment { rgb <1, 1, 0.3> } }
triangle { <0, -2, -2>, <0, 2, -2>, <0, 0, 2> pigment { rgb <0.8, 0.5, 1> } }
plane { y, -2 pigment { rgb 0.6 } }
