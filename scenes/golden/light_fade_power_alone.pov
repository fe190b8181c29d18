// fade_power without fade_distance: POV-Ray 3.7 fades nothing (Attenuate_Light needs a
// fade_distance); with one, 2 / (1 + (d / fade_distance)^fade_power).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -6> look_at 0 }
light_source { <-2, 3, -3> rgb 0.6 fade_power 2 }
light_source { <3, 2, -2> rgb <0.4, 0.3, 0.2> fade_power 1 fade_distance 2 }
sphere { 0, 1 pigment { rgb 1 } }
plane { y, -1 pigment { checker rgb 0.6 rgb 0.3 } }
