// A 3.7 scene with assumed_gamma 2.2: image files decode to linear and encode to the
// working gamma, except Netpbm and TIFF files, whose values POV-Ray takes as they are
// (working-space values) unless a gamma is given; sRGB colours decode into the working
// gamma too.
#version 3.7;
global_settings { assumed_gamma 2.2 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
#macro Tile(Pigment, X, Y)
  box { <0, 0, 0>, <1.8, 2.6, 0.5>
        pigment { Pigment scale <1.8, 2.6, 1> } finish { ambient 1 diffuse 0 } translate <X, Y, 0> }
#end
Tile(pigment { image_map { pgm "images/card.pgm" } }, -3.9, 0.1)
Tile(pigment { image_map { tiff "images/card.tif" } }, -1.95, 0.1)
Tile(pigment { image_map { ppm "images/card.ppm" } }, 0, 0.1)
Tile(pigment { image_map { png "images/card.png" } }, 1.95, 0.1)
Tile(pigment { image_map { pgm "images/card.pgm" gamma 1.6 } }, -3.9, -2.7)
Tile(pigment { image_map { exr "images/card.exr" } }, -1.95, -2.7)
Tile(pigment { image_map { jpeg "images/card.jpg" } }, 0, -2.7)
box { <1.95, -2.7, 0>, <3.9, -0.1, 0.5> pigment { checker srgb 0.3 srgb <0.9, 0.6, 0.2> scale 0.4 }
      finish { ambient 1 diffuse 0 } }
