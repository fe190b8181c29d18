// Light groups with media (POV-Ray 3.7's ComputeMediaLightInterval): a stretch of media
// along a ray is lit by the lights of the object the ray ends on, the global ones only
// unless that object's group turned them off; a ray that ends on an object outside the
// groups, or hits nothing, sees the global lights. The atmosphere in front of the left
// sphere glows red only (its group has global_lights off), in front of the box blue and
// white (global_lights on); the container's media in front of the right sphere glows in
// its group's green light and the global one; a negative group light darkens the media
// in front of its disc. Method 3 without jitter: deterministic.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -8> look_at <0, 1, 0> angle 50 }
light_source { <-4, 8, -3> color rgb 0.8 }
plane { y, 0 pigment { rgb 0.6 } }
plane { z, 3 pigment { rgb 0.5 } }
media { scattering { 1, rgb 0.04 } intervals 2 samples 3 method 3 }
light_group {
  light_source { <-2.5, 3, -2> color rgb <1.5, 0.3, 0.2> }
  sphere { <-2.5, 1, 0>, 0.9 pigment { rgb 1 } }
}
light_group {
  light_source { <0, 4, -3> color rgb <0.3, 0.5, 1.5> }
  box { <-0.6, 0, -0.5>, <0.6, 1.8, 0.5> pigment { rgb 0.9 } }
  global_lights on
}
box { <1.3, 0.01, -1.2>, <3.7, 2.5, 1.2> hollow pigment { rgbt 1 }
  interior { media { scattering { 1, rgb 0.15 } absorption 0.05 intervals 3 } } }
light_group {
  light_source { <2.5, 2.2, -0.5> color rgb <0.2, 1.2, 0.3> }
  sphere { <2.5, 0.8, 0.2>, 0.6 pigment { rgb 1 } }
  global_lights on
}
light_group {
  light_source { <-1, 1, -4> color rgb -1.5 }
  disc { <-1.2, 2.6, 2.9>, z, 0.7 pigment { rgb 0.8 } }
  global_lights on
}
