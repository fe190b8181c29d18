// Text at extreme scales and places: tiny glyphs (1e-3) near the camera, huge ones far
// away, text far from the origin, text seen edge-on and nearly along z (the glyph
// solver's absolute 1e-10 thresholds act in em units, so scaling changes which
// near-tangent rays they drop).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.2, -6> look_at <0, 0, 0> angle 50 }
light_source { <10, 20, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
text { ttf "timrom.ttf" "tiny" 0.5, 0 scale 1e-3 translate <-0.002, 0.2, -5.99>
       pigment { rgb <1, 0.6, 0.2> } }
text { ttf "cyrvetic.ttf" "HUGE" 20, 0 scale 300 translate <-700, -100, 5000>
       pigment { rgb <0.6, 0.8, 1> } }
text { ttf "crystal.ttf" "far" 0.3, 0 translate <1e5, 0, 0> translate <-1e5 - 2.5, -1.5, 0>
       pigment { rgb <0.8, 1, 0.6> } }
text { ttf "timrom.ttf" "edge" 2, 0 rotate 90*y translate <1.2, -0.2, -1>
       pigment { rgb 1 } }
text { ttf "timrom.ttf" "OQ@" 1e-4, 0 rotate <-30, 20, 0> translate <-1, -0.9, 0>
       pigment { rgb <1, 0.7, 0.9> } }
