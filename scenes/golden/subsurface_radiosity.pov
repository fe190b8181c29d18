// golden-args: --block-mean 8
// Subsurface with radiosity: the ordinary radiosity ambient is added on top of the subsurface
// light, and radiosity sample rays see the subsurface sphere without its diffuse term.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  mm_per_unit 10
  subsurface { samples 20, 4 }
  radiosity { pretrace_start 0.08 pretrace_end 0.04 count 35 recursion_limit 1 nearest_count 5 error_bound 1.5 }
}
camera { location <0, 1.2, -1.9> look_at <0, 0.6, 0> angle 60 }
light_source { <-1.2, 2.5, -1.5> color rgb 1 }
box { <-2, -0.001, -2>, <2, 3, 3> hollow pigment { color rgb <1, 0.4, 0.3> } finish { diffuse 0.8 ambient 0 } }   // room, reddish walls for colour bleeding
sphere { <0, 0.6, 0>, 0.6
  pigment { color rgb <0.9, 0.9, 0.85> }
  finish { diffuse 0.9 ambient 0 subsurface { translucency 1.0 } }
  interior { ior 1.3 }
}
