// golden-args: --block-mean 8 --max-rmse 0.03 --fail 0.06 --max-bad-fraction 0
// Radiosity `media on`: the sample rays see media and fog as the camera's rays do, so
// the glowing emission-media sphere lights the room, and the scattering box and the fog
// dim what the sample rays gather (radiosity_media.pov is the same scene with it off).
#version 3.7;
global_settings { assumed_gamma 1.0
  radiosity { pretrace_start 0.08 pretrace_end 0.02 count 80 error_bound 0.8
              recursion_limit 2 brightness 1.0 gray_threshold 0.2 media on } }
camera { location <0, 1.5, -4> look_at <0, 0.8, 0> angle 50 }
light_source { <1, 2.3, -1> rgb 0.5 }
box { <-2, 0, -4.5>, <2, 2.5, 2> inverse pigment { rgb 0.7 } finish { diffuse 0.7 } }
sphere { 0, 1 pigment { rgbt 1 } hollow
  interior { media { emission <4, 3, 1.5> } } scale 0.4 translate <1.4, 0.45, 0.8> }
box { <-1.3, 0, -0.3>, <-0.3, 1, 0.7> pigment { rgbt 1 } hollow
  interior { media { scattering { 1, 0.6 } absorption 0.3 } } }
box { <0.2, 0, -1.2>, <0.6, 0.4, -0.8> pigment { rgb <0.9, 0.4, 0.3> } finish { diffuse 0.7 } }
fog { distance 40 rgb <0.4, 0.45, 0.5> }
