// `hollow` on a difference reaches its children as on an intersection (POV-Ray's
// difference is one): the shell's media render, lit by a spot light (scattering),
// glowing (emission); a nested difference inside a union too.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -6> look_at <0, 0.3, 0> angle 45 }
light_source { <2, 6, -3> color rgb 1.5 spotlight point_at 0 radius 20 falloff 30 }
plane { y, -1.6 pigment { checker rgb 0.8 rgb 0.4 } }
difference {
  sphere { 0, 1.5 }
  sphere { 0, 1 }
  hollow
  pigment { rgbf 1 }
  interior { media { emission 0.15 scattering { 4, 0.4 } } }
  translate -1.2 * x
}
union {
  difference { box { -0.8, 0.8 } sphere { 0, 0.95 } }
  sphere { 0.5 * y, 0.3 }
  hollow
  pigment { rgbt 1 }
  interior { media { scattering { 1, <0.3, 0.5, 0.6> } } }
  translate <1.6, -0.2, 0>
}
