// Scattering media lit by area_illumination lights: POV-Ray's media sample takes such a
// light unattenuated (no fade, no falloff inside the spot's interval), its shadow the
// adaptive grid's. Method 3, jitter 0.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -6> look_at <0, 1, 0> angle 50 }
light_source { <1, 4, 1> color rgb 1 area_light 2*x, 2*z, 3, 3 adaptive 1 area_illumination fade_distance 2 fade_power 2 }
light_source { <-3, 3, -2> color rgb 0.8 area_light x, y, 3, 3 adaptive 0 area_illumination spotlight point_at <0,1,0> radius 15 falloff 25 }
plane { y, 0 pigment { rgb 0.7 } }
sphere { <0.5, 2.2, 0.5>, 0.4 pigment { rgb 0.3 } }
box { <-2, 0.01, -1>, <2, 2, 2> hollow pigment { rgbt 1 } interior { media { scattering { 2, 0.3 } absorption 0.05 } } }
