// density_file df3 in media: one 12x10x7 8-bit grid (scenes/golden/density_cloud.df3) with
// interpolate 0 (nearest voxel), 1 (trilinear) and 2 (tricubic, whose values above 1
// wrap through the pattern's frequency), each neighbour reaching across the far faces to
// the near ones as POV-Ray's index arithmetic does. The boxes stop just inside the unit
// cube: the density drops to 0 at its faces, and method 3 samples the interval ends, where
// a last-bit difference in the hit point would pick either side.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.8, -5> look_at <0, 0.1, 0> angle 58 }
background { color rgb 0.02 }
light_source { <3, 6, -5> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.45 rgb 0.25 } }
#macro CloudBox(Interpolation, Position)
  box { 0.0005, 0.9995 hollow pigment { rgbt 1 }
    interior { media { emission 0.9 absorption 2 samples 4
      density { density_file df3 "density_cloud.df3" interpolate Interpolation
        color_map { [0 rgb 0] [0.3 rgb <0.8, 0.3, 0.1>] [0.7 rgb <0.2, 0.6, 1>] [1 rgb 1] } } } }
    translate -0.5 scale 1.55 rotate <20, 30, 0> translate Position }
#end
CloudBox(0, <-1.7, 0, 0>)
CloudBox(1, <0, 0, 0>)
CloudBox(2, <1.7, 0, 0>)
