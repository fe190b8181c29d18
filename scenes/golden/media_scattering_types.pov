// Media scattering, method 3 (POV-Ray's 3.7 default, deterministic with jitter 0): the
// five phase functions side by side in hollow boxes lit by a point light from behind and
// a spot light across (its cone limits the lit intervals), with a shadow-casting sphere
// in the light's way and a filtering pane.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -9> look_at <0, 1.2, 0> angle 60 }
light_source { <2, 8, 6> color rgb 1.2 }
light_source { <-6, 5, -2> color rgb <1, 0.9, 0.7>
  spotlight point_at <0, 1, 1> radius 10 falloff 18 tightness 5 }
light_source { <0, 10, -10> color rgb 0.4 media_interaction off }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
sphere { <0.8, 3.2, 2.5>, 0.5 pigment { rgb <0.9, 0.2, 0.2> } }
box { <-4, 2.8, 1.8>, <-2, 2.9, 3.8> pigment { rgbf <0.3, 0.9, 0.4, 0.8> } }
#macro Slab(X)
  box { <X - 0.7, 0.01, 0>, <X + 0.7, 2.6, 2> hollow pigment { rgbt 1 } }
#end
object { Slab(-3.6) interior { media { scattering { 1, rgb 0.5 } } } }
object { Slab(-1.8) interior { media { scattering { 2, rgb <0.5, 0.4, 0.3> } } } }
object { Slab(0) interior { media { scattering { 3, rgb 0.4 extinction 0.5 } } } }
object { Slab(1.8) interior { media { scattering { 4, rgb <0.3, 0.4, 0.6> } } } }
object { Slab(3.6) interior { media { scattering { 5, rgb 0.5 eccentricity -0.6 } } } }
