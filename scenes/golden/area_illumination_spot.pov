// area_illumination on a spotlight area light close to the floor: each sample's cone
// (tightness, the falloff between radius and falloff) is read from its own ray, so the
// pool of light is the samples' cones blended. A cylinder area light's samples fade each
// over their own depth. No jitter, full grids.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4.5, -6> look_at <0, 0.3, 0.5> angle 55 }
light_source { <-1.2, 1.8, 0> color rgb 1.6
  spotlight point_at <-1.2, 0, 0.2> radius 30 falloff 45 tightness 3
  area_light <3, 0, 0>, <0, 0, 3>, 5, 5
  area_illumination on }
light_source { <2, 3, -1> color rgb <0.6, 0.6, 0.8>
  cylinder point_at <2, 0, 0> radius 1 falloff 1.6 tightness 1
  area_light <1, 0, 0>, <0, 0, 1>, 3, 3
  fade_distance 1 fade_power 1
  area_illumination on }
light_source { <0, 8, -6> color rgb 0.12 }
plane { y, 0 pigment { rgb 0.8 } finish { specular 0.5 roughness 0.02 } }
sphere { <-1.2, 0.45, 0.3>, 0.45 pigment { rgb <0.9, 0.5, 0.2> } finish { phong 0.7 phong_size 30 } }
sphere { <2, 0.4, 0.2>, 0.4 pigment { rgb <0.5, 0.7, 1> } finish { phong 0.7 phong_size 30 } }
