// Media with density patterns: method 3 with adaptive refinement (aa_level 4, a tight
// threshold), method 2 without jitter over several intervals, two media in one interior,
// densities that multiply, and densities moved with their object.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 0.8, 0> angle 55 }
light_source { <3, 6, -5> color rgb 1 }
background { color rgb 0.05 }
plane { y, -0.2 pigment { rgb 0.6 } }
sphere { 0, 1 hollow pigment { rgbt 1 }
  interior {
    media { emission 1.5 aa_level 4 aa_threshold 0.02 samples 6
            density { spherical color_map { [0 rgb 0] [0.6 rgb <1, 0.6, 0.2>] [1 rgb 1] } } }
    media { absorption 0.8 density { gradient y color_map { [0 rgb 0.2] [1 rgb 1] } } } }
  translate <-1.5, 1, 0> }
box { -1, 1 hollow pigment { rgbt 1 }
  interior {
    media { method 2 intervals 5 samples 3 emission <0.3, 0.7, 1.2> absorption 0.5
            density { bozo color_map { [0 rgb 0] [1 rgb 1] } scale 0.4 }
            density { gradient x color_map { [0 rgb 1] [1 rgb 0.3] } } } }
  scale <0.9, 1, 0.9> rotate y * 30 translate <1.4, 0.9, 0.5> }
