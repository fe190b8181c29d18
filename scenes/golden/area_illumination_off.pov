// area_illumination off (named): the area light lights the surfaces from its centre,
// its grid giving the shadows only. The scene of area_illumination.pov otherwise.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.5, -6> look_at <0, 0.6, 0> angle 50 }
light_source { <0, 2.2, 0> color rgb 1.3
  area_light <5, 0, 0>, <0, 0, 3>, 6, 4
  fade_distance 2 fade_power 1
  area_illumination off }
light_source { <-6, 8, -8> color rgb 0.15 }
plane { y, 0 pigment { rgb 0.75 } finish { specular 0.4 roughness 0.02 } }
sphere { <-1.4, 0.7, 0>, 0.7 pigment { rgb <0.9, 0.4, 0.3> } finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.6>, <1.4, 0.9, 0.4> pigment { rgb <0.3, 0.6, 0.9> } finish { specular 0.6 roughness 0.01 } }
sphere { <2.2, 0.35, -1.2>, 0.35 pigment { rgb 0.9 } finish { phong 1 phong_size 200 metallic 0.5 } }
