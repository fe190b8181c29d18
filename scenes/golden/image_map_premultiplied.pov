// POV-Ray 3.7's premultiplied alpha in image maps: its TIFF and OpenEXR readers keep
// colours premultiplied, and `premultiplied on` makes any file's so; the image_map
// pigment then divides its (interpolated) sample by 1 - transmit, `transmit all`
// included, so a TIFF or EXR without alpha under `transmit all 0.4` shows its colours
// divided by 0.6. `premultiplied off` keeps them as stored.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
background { rgb <0.2, 0.3, 0.5> }
#macro Tile(Pigment, X, Y)
  box { <0, 0, 0>, <1.8, 2.6, 0.5>
        pigment { Pigment scale <1.8, 2.6, 1> } finish { ambient 1 diffuse 0 } translate <X, Y, 0> }
#end
Tile(pigment { image_map { png "images/card_alpha.png" premultiplied on } }, -3.9, 0.1)
Tile(pigment { image_map { png "images/card_alpha.png" premultiplied on interpolate 2 } }, -1.95, 0.1)
Tile(pigment { image_map { png "images/card_alpha.png" premultiplied off } }, 0, 0.1)
Tile(pigment { image_map { tiff "images/card.tif" transmit all 0.4 } }, 1.95, 0.1)
Tile(pigment { image_map { exr "images/card.exr" transmit all 0.3 interpolate 2 } }, -3.9, -2.7)
Tile(pigment { image_map { tiff "images/card.tif" premultiplied off transmit all 0.4 } }, -1.95, -2.7)
Tile(pigment { image_map { png "images/card.png" premultiplied 1 filter all 0.3 transmit all 0.2 } }, 0, -2.7)
Tile(pigment { image_map { exr "images/card.exr" premultiplied 0 transmit all 0.3 } }, 1.95, -2.7)
