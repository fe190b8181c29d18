// area_illumination with adaptive grids: the shadow is POV-Ray's adaptive average, refined
// where corners differ by more than 0.1 in the light's own colour (not faded: the samples
// are faded each when they light), while every point of the grid lights the surface. A
// second, circular light faces each point (orient). No jitter.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6.5> look_at <0, 0.5, 0> angle 50 }
light_source { <-0.5, 2.5, 0.5> color rgb 1.1
  area_light <4, 0, 0>, <0, 0, 4>, 9, 9 adaptive 1
  fade_distance 1.5 fade_power 2
  area_illumination }
light_source { <2.5, 1.8, -1.5> color rgb <0.5, 0.45, 0.3>
  area_light <1.5, 0, 0>, <0, 1.5, 0>, 5, 5 adaptive 0 circular orient
  area_illumination on }
plane { y, 0 pigment { rgb 0.8 } finish { phong 0.3 phong_size 20 } }
sphere { <-1, 0.8, 0.2>, 0.8 pigment { rgb <0.4, 0.8, 0.4> } finish { specular 0.7 roughness 0.005 } }
cylinder { <1.2, 0, 0.8>, <1.2, 1.6, 0.8>, 0.3 pigment { rgb <0.9, 0.8, 0.5> } finish { phong 0.6 phong_size 60 } }
box { <-0.3, 1.2, -1.4>, <0.5, 1.3, -0.6> pigment { rgb 0.6 } }
