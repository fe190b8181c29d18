// A font made to meet POV-Ray 3.7's TrueType reading quirks (fonts/make_quirks_font.py):
// even-odd overlap (A), unsigned composite byte offsets (B), a contour starting
// off-curve (D), a transposed composite 2x2 (E); cmap format 0 on the Mac platform only.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <2.6, 0.45, -5> look_at <2.6, 0.45, 0> right 6*x up 4.5*y }
light_source { <-3, 5, -9> color rgb 1 }
background { rgb 0.1 }
text { ttf "fonts/quirks.ttf" "ABCDE" 0.5, 0.1 pigment { rgb <1, 0.8, 0.5> } }
text { ttf "fonts/quirks" "EDCBA" 0.3, 0 pigment { rgb <0.5, 0.8, 1> } rotate <-30, 20, 0>
       translate <0.3, -1.2, 0> }
