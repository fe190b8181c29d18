// rainbow: a band at `angle` from the antisolar `direction`, `width` wide, coloured by
// its colour map (filter lets the scene through, transmit sets the least it lets
// through), fading in with distance (`distance`: the plane nearby shows less of it than
// the sky). A second rainbow with arc_angle and falloff_angle: it shows only within
// half its arc angle of `up`, fading out beyond the falloff angle. Without jitter:
// deterministic.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -10> look_at <0, 4, 0> angle 90 }
background { rgb <0.3, 0.5, 0.9> }
light_source { <-10, 20, -20> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.4 scale 2 } }
rainbow {
  angle 42 width 6 distance 40
  direction <0.1, -0.3, 1>
  colour_map {
    [0.0 colour rgbf <1, 0.5, 1, 1>]
    [0.2 colour rgbf <0.4, 0.4, 1, 0.6>]
    [0.5 colour rgbf <0.2, 1, 0.3, 0.5>]
    [0.8 colour rgbft <1, 0.8, 0.2, 0.4, 0.2>]
    [1.0 colour rgbf <1, 0.2, 0.2, 1>]
  }
}
rainbow {
  angle 30 width 4 distance 1e6
  direction <0.1, -0.3, 1> up <0.3, 1, 0>
  arc_angle 120 falloff_angle 60
  colour_map {
    [0.0 colour rgbf <1, 1, 1, 1>]
    [0.5 colour rgbf <1, 1, 0.6, 0.3>]
    [1.0 colour rgbf <1, 1, 1, 1>]
  }
}
