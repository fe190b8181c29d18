// golden-args: --block-mean 8
// Scattering media under #version 3.1 (method 1, intervals 10, samples 1, as POV-Ray
// defaults them) lit by an area light and two spot lights (the lit intervals split the
// ray for the sample intervals), one spot inside the media; Rayleigh scattering; compared
// as block means since method 1 is random.
#version 3.1;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -7> look_at <0, 1, 0> angle 55 }
light_source { <3, 6, -2> color rgb 0.8 area_light x, z, 3, 3 adaptive 1 }
light_source { <-3, 4, 0> color rgb <1, 0.6, 0.4>
  spotlight point_at <-1, 0, 1> radius 8 falloff 14 }
light_source { <2, 1.5, 0.5> color rgb <0.4, 0.8, 1>
  spotlight point_at <4, 0, 0.5> radius 20 falloff 30 }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.4 } }
box { <-3, 0.01, -1>, <3, 2.8, 2> hollow pigment { rgbt 1 }
  interior { media { scattering { 4, rgb 0.3 } absorption 0.05 } } }
sphere { <0, 3.6, 0>, 0.5 pigment { rgb 0.2 } }
