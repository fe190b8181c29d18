// golden-args: --block-mean 8
// A metal ring's reflection caustic (the cardioid inside it): photons reflected by a
// metallic finish, once or more, from a spotlight.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6
  photons { count 30000 gather 15, 80 autostop 0 } }
camera { location <0, 5, -3.5> look_at <0, 0, 0> angle 45 }
light_source { <-4, 2.5, 0> color rgb 1.5 spotlight point_at <0, 0, 0> radius 25 falloff 35 }
light_source { <0, 10, -10> color rgb 0.3 }
plane { y, 0 pigment { rgb 0.8 } }
difference {
  cylinder { <0, 0, 0>, <0, 0.6, 0>, 1.5 }
  cylinder { <0, -0.1, 0>, <0, 0.7, 0>, 1.4 }
  pigment { rgb <1, 0.8, 0.4> }
  finish { ambient 0 diffuse 0.1 reflection { 0.9 metallic } specular 0.6 metallic }
  photons { target reflection on refraction off }
}
