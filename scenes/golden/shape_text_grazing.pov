// Grazing and axis views of text: the camera nearly in the plane of the faces, text
// lying flat seen along its base line, and a view straight along z (the 0.001-degree
// rotation keeps rays off the parallel branches).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.3, 0.45, -6> look_at <0.3, 0.3, 0> angle 55 }
light_source { <-3, 6, -8> color rgb 1 }
light_source { <4, -2, -5> color rgb 0.3 }
background { rgb <0.3, 0.3, 0.4> }
text { ttf "timrom.ttf" "Flat" 0.05, 0 rotate 90*x translate <-2.2, 0.3, -1>
       pigment { rgb <0.9, 0.5, 0.3> } }
text { ttf "cyrvetic.ttf" "Edge" 3, 0 rotate -89.5*y translate <1.5, -0.6, -2>
       pigment { rgb <0.3, 0.8, 0.9> } }
text { ttf "crystal.ttf" "z" 0.5, 0 translate <-0.5, -1, 0>
       pigment { rgb <0.7, 0.9, 0.4> } }
text { ttf "timrom.ttf" "=" 1, 0 rotate 89.9*y translate <0.2, 0.9, 0>
       pigment { rgb <0.9, 0.9, 0.9> } }
