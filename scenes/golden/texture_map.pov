// texture_map blending whole textures (different finishes, one reflective), and a checker of
// textures: the two entries' colours are blended as POV-Ray does.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 texture { checker texture { pigment { rgb <0.8, 0.8, 0.7> } }
                               texture { pigment { rgb <0.2, 0.3, 0.5> } finish { reflection 0.3 } } } }
sphere { <-1.2, 1, 0>, 1
  texture { gradient x texture_map {
      [0.2 pigment { rgb <1, 0.2, 0.1> } finish { phong 0.8 }]
      [0.8 pigment { rgb <0.1, 0.3, 1> } finish { reflection 0.4 diffuse 0.3 }] }
    scale 2 translate -x } }
box { <0.4, 0, -0.6>, <2, 1.4, 0.6>
  texture { bozo texture_map {
      [0.0 pigment { rgb <1, 1, 0.2> }]
      [0.5 pigment { rgb <0.2, 0.9, 0.3> } finish { specular 0.6 }]
      [1.0 pigment { rgbt <1, 1, 1, 0.7> }] }
    scale 0.3 } }
