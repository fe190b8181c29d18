// Atmospheric scattering media (method 3 with jitter 0, and a second media of another
// type: the phase is averaged over the list) lit by a spot light and a cylinder light,
// both limiting the lit intervals; a light with media_attenuation is dimmed by the
// atmosphere on its way to the surfaces; objects cast volumetric shadows. A hollow
// sky sphere encloses the view.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -8> look_at <0, 1.5, 0> angle 60 }
light_source { <0, 7, 0> color rgb 1.5
  spotlight point_at <0, 0, 0> radius 15 falloff 25 tightness 2 media_attenuation on }
light_source { <-8, 2, 3> color rgb <0.5, 0.6, 1>
  cylinder point_at <0, 2, 3> radius 0.6 falloff 1.0 }
light_source { <5, 6, -6> color rgb 0.5 media_interaction off }
media { scattering { 4, rgb 0.06 } intervals 2 samples 6 ratio 0.7 }
media { scattering { 5, rgb 0.03 eccentricity 0.4 } absorption 0.01 }
sphere { 0, 30 hollow pigment { rgb <0.2, 0.3, 0.5> } finish { emission 1 diffuse 0 } }
plane { y, 0 pigment { rgb 0.7 } }
sphere { <0.5, 3.5, 0.3>, 0.6 pigment { rgb <0.9, 0.8, 0.2> } }
box { <-2, 0, 2.5>, <2, 3.5, 3> pigment { rgb 0.6 } }
