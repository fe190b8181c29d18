// The same card from PNG, TGA and PPM (#version 3.7 decodes PNG and TGA as sRGB and takes
// PPM as linear), an explicit `gamma 1.0` and `gamma 2.2` override, and a file used both
// as image_map and as a spherical map with `once` lying on a plane.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
#macro Tile(File, Type, X, Y)
  box { <0, 0, 0>, <2.4, 2.6, 0.5>
        pigment { image_map { Type File } scale <2.4, 2.6, 1> }
        finish { ambient 1 diffuse 0 } translate <X, Y, 0> }
#end
box { <-3.9, 0.1, 0>, <-1.5, 2.7, 0.5>
      pigment { image_map { png "images/card.png" } scale <2.4, 2.6, 1> translate <-3.9, 0.1, 0> }
      finish { ambient 1 diffuse 0 } }
box { <-1.2, 0.1, 0>, <1.2, 2.7, 0.5>
      pigment { image_map { tga "images/card.tga" } scale <2.4, 2.6, 1> translate <-1.2, 0.1, 0> }
      finish { ambient 1 diffuse 0 } }
box { <1.5, 0.1, 0>, <3.9, 2.7, 0.5>
      pigment { image_map { ppm "images/card.ppm" } scale <2.4, 2.6, 1> translate <1.5, 0.1, 0> }
      finish { ambient 1 diffuse 0 } }
box { <-3.9, -2.7, 0>, <-1.5, -0.1, 0.5>
      pigment { image_map { png "images/card.png" gamma 1.0 } scale <2.4, 2.6, 1> translate <-3.9, -2.7, 0> }
      finish { ambient 1 diffuse 0 } }
box { <-1.2, -2.7, 0>, <1.2, -0.1, 0.5>
      pigment { image_map { "images/card.ppm" gamma 2.2 interpolate 2 } scale <2.4, 2.6, 1> translate <-1.2, -2.7, 0> }
      finish { ambient 1 diffuse 0 } }
sphere { <2.7, -1.4, 0>, 1.2
      pigment { image_map { png "images/card.png" map_type 1 once } }
      finish { ambient 1 diffuse 0 } }
