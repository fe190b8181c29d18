// golden-args: --block-mean 8 --max-rmse 0.03 --fail 0.04 --max-bad-fraction 0
// Radiosity outdoors: no light source, only a sky_sphere (a gradient from the horizon
// up) whose light the sample rays gather; objects on a ground plane are lit from the
// sky and shade each other where they are close (the sky is occluded). A recursion limit
// of 1 and a max_sample cap.
#version 3.7;
global_settings { assumed_gamma 1.0
  radiosity { pretrace_start 0.08 pretrace_end 0.02 count 60 nearest_count 5
              error_bound 1 recursion_limit 1 max_sample 2 } }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> angle 45 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.9, 1>] [1 rgb <0.2, 0.4, 1>] } } }
plane { y, 0 pigment { rgb 0.8 } }
sphere { <-0.8, 0.7, 0>, 0.7 pigment { rgb <1, 0.8, 0.5> } }
box { <0.2, 0, -0.5>, <1.4, 1.2, 0.5> rotate y * 30 pigment { rgb 0.8 } }
torus { 0.5, 0.15 translate <0.2, 0.15, -1.3> pigment { rgb <0.5, 0.8, 0.5> } }
