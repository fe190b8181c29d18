// The card from every other file type POV-Ray 3.7 reads: BMP, GIF (a palette), JPEG,
// TIFF and PGM (linear: no gamma in the file), OpenEXR and Radiance HDR (linear), and bump
// maps with use_index (of a true-colour PNG: its grey, as use_colour) and use_colour.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-5, 5, -10> color rgb 1 }
#macro Tile(Pigment, X, Y)
  box { <0, 0, 0>, <1.8, 2.6, 0.5>
        pigment { Pigment scale <1.8, 2.6, 1> } finish { ambient 1 diffuse 0 } translate <X, Y, 0> }
#end
Tile(pigment { image_map { bmp "images/card.bmp" } }, -3.9, 0.1)
Tile(pigment { image_map { gif "images/card.gif" } }, -1.95, 0.1)
Tile(pigment { image_map { jpeg "images/card.jpg" } }, 0, 0.1)
Tile(pigment { image_map { tiff "images/card.tif" } }, 1.95, 0.1)
Tile(pigment { image_map { exr "images/card.exr" } }, -3.9, -2.7)
Tile(pigment { image_map { hdr "images/card.hdr" } }, -1.95, -2.7)
Tile(pigment { image_map { pgm "images/card.pgm" } }, 0, -2.7)
box { <1.95, -2.7, 0>, <3.9, -1.45, 0.5>
      pigment { rgb 0.8 } finish { ambient 0.1 diffuse 0.9 }
      normal { bump_map { png "images/card.png" use_index bump_size 3 } scale <1.95, 1.25, 1> translate <1.95, -2.7, 0> } }
box { <1.95, -1.35, 0>, <3.9, -0.1, 0.5>
      pigment { rgb 0.8 } finish { ambient 0.1 diffuse 0.9 }
      normal { bump_map { gif "images/card.gif" use_colour bump_size 3 } scale <1.95, 1.25, 1> translate <1.95, -1.35, 0> } }
