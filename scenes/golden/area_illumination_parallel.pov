// area_illumination on parallel area lights: each sample's rays (lighting and shadow) run
// from point_at through it, its depth measured along them; the fade past the plane of a
// far sample turns negative, as POV-Ray's. A parallel spotlight's samples each read its
// cone; that light also faces each point (orient, circular). No jitter.
global_settings { assumed_gamma 1.0 }
camera { location <0, 4.5, -6> look_at <0, 0.3, 0.5> angle 55 }
light_source { <-1, 3, -1> color rgb 1 parallel point_at <0, 0, 0>
  area_light <3, 0, 0>, <0, 0, 3>, 5, 5 fade_distance 2 fade_power 1
  area_illumination on }
light_source { <2, 2, 0> color rgb 0.7 spotlight parallel point_at <1.5, 0, 0.5> radius 20 falloff 40 tightness 2
  area_light <2, 0, 0>, <0, 2, 0>, 4, 4 orient circular
  area_illumination on }
plane { y, 0 pigment { rgb 0.8 } finish { specular 0.5 roughness 0.02 } }
sphere { <-1.2, 0.45, 0.3>, 0.45 pigment { rgb <0.9, 0.5, 0.2> } finish { phong 0.7 phong_size 30 } }
sphere { <1.5, 0.4, 0.2>, 0.4 pigment { rgb <0.5, 0.7, 1> } finish { phong 0.7 phong_size 30 } }
