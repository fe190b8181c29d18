// Finish: ambient, diffuse, brilliance, phong/phong_size, specular/roughness, metallic.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <1, 0.9, 0.9> }
camera { location <0, 0, -9> look_at 0 angle 45 }
light_source { <-5, 6, -8> color rgb 1 }
light_source { <6, 2, -6> color rgb <0.4, 0.4, 0.6> }
background { color rgb 0.05 }
#declare P = pigment { color rgb <0.8, 0.5, 0.3> };
sphere { <-3, 1.2, 0>, 1 pigment { P } finish { ambient 0.3 diffuse 0.4 } }
sphere { <0, 1.2, 0>, 1 pigment { P } finish { diffuse 0.8 brilliance 3 } }
sphere { <3, 1.2, 0>, 1 pigment { P } finish { phong 0.9 phong_size 80 } }
sphere { <-3, -1.2, 0>, 1 pigment { P } finish { phong 0.6 phong_size 10 } }
sphere { <0, -1.2, 0>, 1 pigment { P } finish { specular 0.8 roughness 0.01 } }
sphere { <3, -1.2, 0>, 1 pigment { P } finish { specular 0.7 roughness 0.1 metallic } }
