// golden-args: File_Gamma=1.0
// File_Gamma in a legacy scene (#version 3.6, no assumed_gamma): POV-Ray writes its values
// raw whatever the file gamma is (it takes the display gamma for both ends), so the image is
// the one without the option.
#version 3.6;
camera { location <0, 1, -4> look_at <0, 0.2, 0> }
light_source { <5, 5, -5> color rgb 1 }
sphere { 0, 1 pigment { color rgb <0.8, 0.4, 0.05> } finish { phong 0.5 } }
plane { y, -1 pigment { gradient x color_map { [0 rgb 0.002] [1 rgb 1] } scale 4 translate -2*x } }
background { rgb <0.2, 0.3, 0.5> }
