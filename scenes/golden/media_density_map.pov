// A density_map: densities blended by a pattern as a pigment_map blends pigments
// (declared densities and an inline pattern, colour maps inside), in an emitting and
// scattering media (method 3, jitter 0).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at 0 angle 45 }
light_source { <3, 5, -4> color rgb 1 }
#declare Glow = density { spherical ramp_wave
  color_map { [0 rgb 0] [0.2 rgb <1, 0.3, 0.1>] [1 rgb <1, 1, 0.1>] } }
#declare Box = density { boxed ramp_wave
  color_map { [0 rgb 0] [0.2 rgb <0.1, 1, 0.3>] [1 rgb <0.1, 1, 1>] } }
sphere { 0, 1.5 hollow pigment { rgbt 1 }
  interior { media {
    emission 0.6 scattering { 1, 0.2 }
    density { gradient x density_map {
      [0.3 Glow]
      [0.5, bozo scale 0.3 color_map { [0 rgb 0] [1 rgb <0.4, 0.4, 1>] }]
      [0.7 Box] }
      scale 3 translate -1.5 * x } } } }
plane { y, -1.5 pigment { checker rgb 0.8 rgb 0.4 } }
