// golden-args: --block-mean 8 --max-rmse 0.03 --fail 0.06 --max-bad-fraction 0
// Radiosity from emission: no light source; a glowing sphere (finish emission, no
// diffuse) is the only source, and a no_radiosity glowing disc shows in the image but
// not in the sample rays. The objects' `ambient` is ignored under radiosity (#version
// 3.7); the ceiling's diffuse albedo scales its direct light but not its radiosity.
#version 3.7;
global_settings { assumed_gamma 1.0
  radiosity { pretrace_start 0.08 pretrace_end 0.02 count 80 error_bound 0.8
              recursion_limit 2 brightness 1.2 gray_threshold 0.2 } }
camera { location <0, 1.5, -4> look_at <0, 0.8, 0> angle 50 }
box { <-2, 0, -4.5>, <2, 2.5, 2> inverse pigment { rgb 0.7 } finish { ambient 0.5 diffuse 0.7 } }
sphere { <0.6, 0.5, 0.3>, 0.4 pigment { rgb <1, 0.9, 0.6> } finish { emission 3 diffuse 0 } }
disc { <-1.99, 1.5, 0.5>, x, 0.4 pigment { rgb <0.3, 0.3, 1> } finish { emission 4 diffuse 0 }
       no_radiosity }
box { <-1.2, 0, -0.2>, <-0.4, 0.8, 0.6> pigment { rgb <0.9, 0.4, 0.3> } finish { diffuse 0.7 } }
sphere { <0, 0.3, -0.8>, 0.3 pigment { rgb 0.9 } finish { diffuse 0.8 } }
