// Transformed boxes and spheres (translate, rotate, scale, matrix), planes with offsets.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 50 }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <5, 3, -2> color rgb 0.3 shadowless }
plane { y, -0.2 pigment { color rgb <0.7, 0.7, 0.7> } }
plane { <0, 0, -1>, -5 pigment { color rgb <0.5, 0.6, 0.8> } }
box { -0.5, 0.5 rotate <20, 35, 0> translate <-2, 1, 0> pigment { color rgb <0.9, 0.2, 0.3> } }
box { <0, 0, 0>, <1, 1, 1> scale <0.5, 2, 0.5> rotate y * 45 translate <0, 0, 1>
      pigment { color rgb <0.2, 0.8, 0.4> } finish { phong 0.7 } }
sphere { 0, 1 scale <1.2, 0.6, 0.6> rotate z * 30 translate <2.2, 1, 0>
         pigment { color rgb <0.3, 0.3, 0.9> } finish { specular 0.6 } }
sphere { 0, 0.5 matrix <1, 0, 0, 0.5, 1, 0, 0, 0, 1, 0, 2.5, -1> pigment { color rgb 1 } }
