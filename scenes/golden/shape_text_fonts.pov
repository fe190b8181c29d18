// text with each shipped font: kerning pairs (timrom "AV", "To"), thickness and offset,
// a leading space, a rotated and a scaled text. Also rendered in every mode
// (tests/distrib/tcp_test.cpp).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -10> look_at <0, 0.2, 0> angle 56 }
light_source { <-5, 8, -9> color rgb 1 }
light_source { <6, 3, -4> color rgb 0.4 }
plane { y, -2.2 pigment { checker rgb 0.9 rgb 0.6 } }
text { ttf "timrom.ttf" "AVAToWa" 0.4, 0
       pigment { rgb <0.9, 0.3, 0.2> } translate <-3.9, 1.5, 0> }
text { ttf "cyrvetic" "Kern: AV" 1, <0.05, 0.02, 0.3>
       pigment { rgb <0.2, 0.6, 0.9> } translate <-0.3, 1.6, 0> }
text { ttf "crystal.ttf" " Crystal 3.7" 0.2, 0
       pigment { rgb <0.3, 0.8, 0.3> } rotate <10, -25, 0> translate <-3.9, 0.2, 0> }
text { ttf "povlogo.ttf" "P" 0.6, 0
       pigment { rgb <0.9, 0.8, 0.2> } scale 1.4 rotate 20*y translate <1.6, -0.2, -0.5> }
text { ttf "timrom.ttf" "gjq@&%" 2, 0.1
       pigment { rgb <0.8, 0.5, 0.9> } scale <0.9, 1.2, 0.5> rotate -30*x translate <-3.5, -1.6, 0> }
