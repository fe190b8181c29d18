// text { internal N }: 1 timrom, 2 cyrvetic, 3 crystal, anything else povlogo; a float
// offset (moves y too) and a vector offset whose z never reaches the glyphs; an empty
// string and a string of spaces.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -10> look_at <0, 0, 0> angle 45 }
light_source { <-3, 6, -10> color rgb 1 }
light_source { <8, 2, -2> color rgb 0.3 }
background { rgb <0.2, 0.25, 0.3> }
text { internal 1 "POV-Ray" 0.25, 0 pigment { rgb 1 } translate <-3.5, 1.8, 0> }
text { internal 2 "Cyr" 0.5, 0.1 pigment { rgb <1, 0.5, 0.3> } translate <1, 1.8, 0> }
text { internal 3 "Version 3.7" 0.1, <0.02, -0.05, 5> pigment { rgb <0.4, 0.9, 0.5> }
       translate <-3.8, 0.4, 0> }
text { internal 0 "ab" 1, 0 pigment { rgb <0.9, 0.9, 0.3> } translate <1.5, 0.3, 0> }
text { internal 7.9 "X" 1, 0 pigment { rgb <0.6, 0.6, 1> } scale <1/0.7, 1/0.66, 1>
       translate <-1, -1.6, 0> }
text { internal 1 "" 1, 0 pigment { rgb 1 } }
text { internal 1 "   " 1, 0 pigment { rgb 1 } }
text { internal -1 "W" 0.3, 0 pigment { rgb <1, 0.4, 0.8> } rotate <0, 50, 0>
       translate <1.5, -1.8, 0> }
