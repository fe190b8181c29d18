// Cylinder (closed and open), cone, torus (quartic), disc with a hole, triangle.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 55 }
light_source { <-4, 9, -6> color rgb 1 }
plane { y, 0 pigment { color rgb 0.7 } }
cylinder { <-3.5, 0, 0>, <-3.5, 2, 0>, 0.6 pigment { color rgb <1, 0.3, 0.3> } finish { phong 0.6 } }
cylinder { <-2, 0.5, -1>, <-1, 1.5, 0>, 0.3 open pigment { color rgb <1, 1, 0.3> } }
cone { <0, 0, 0>, 0.9, <0, 2, 0>, 0.2 pigment { color rgb <0.3, 1, 0.3> } finish { specular 0.5 } }
torus { 0.8, 0.25 rotate x * 60 translate <2.2, 1, 0> pigment { color rgb <0.3, 0.3, 1> } finish { phong 0.8 } }
disc { <3.5, 0.01, -2>, y, 0.8, 0.3 pigment { color rgb <1, 0.5, 0> } }
triangle { <-1, 0, -2>, <1, 0, -2.5>, <0, 1.5, -2> pigment { color rgb <0.6, 0.2, 0.8> } }
