// golden-args: +A0.3 +AM1 +R3 -J File_Gamma=1.8
// The 3.6 form of assumed_gamma_srgb.pov, written with File_Gamma 1.8: image files are
// taken to be in the working gamma (sRGB), so they are read as they are (a Netpbm file
// too); the output linearises with sRGB's curve and encodes with the power 1/1.8.
#version 3.6;
global_settings { assumed_gamma srgb }
camera { location <0, 2.2, -6> look_at <0, 0.6, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <5, 3, -6> color srgb 0.4 }
plane { y, 0 pigment { checker srgb <0.8, 0.7, 0.5> rgb 0.2 scale 0.7 } finish { diffuse 0.7 } }
sphere { <-1.6, 0.7, 0>, 0.7 pigment { srgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <0, 0.7, 0.6>, 0.7 pigment { rgbf <0.6, 0.9, 0.6, 0.7> } interior { ior 1.4 }
         finish { reflection 0.1 } }
sphere { <1.6, 0.7, 0>, 0.7
         pigment { hexagon srgbt <0.2, 0.4, 0.9, 0.3> red 1 green 0.5 srgbf <0.9, 0.9, 0.2, 0.5>
                   scale 0.2 } }
box { <-0.5, 0, -1.6>, <0.5, 0.5, -1.1>
      pigment { gradient x colour_map { [0 srgb 0.1] [1 srgb <1, 0.8, 0.2>] } } }
#macro Card(Pigment, X)
  box { <0, 0, 0>, <0.9, 1.3, 0.1> pigment { Pigment scale <0.9, 1.3, 1> }
        finish { ambient 1 diffuse 0 } rotate y * 10 translate <X, 1.7, 1.5> }
#end
Card(pigment { image_map { png "images/card.png" } }, -2.6)
Card(pigment { image_map { pgm "images/card.pgm" } }, -1.5)
Card(pigment { image_map { png "images/card.png" gamma 1.8 } }, -0.4)
Card(pigment { image_map { tga "images/card.tga" } }, 0.7)
Card(pigment { image_map { exr "images/card.exr" } }, 1.8)
