// The density_file pattern on surfaces: 8, 16 and 32 bit df3 grids (the width follows
// from the file's length), interpolate 0, 1, 2 and the values POV-Ray reads modulo 10
// (11 is trilinear, -1 tricubic), a name found with ".df3" appended, 0 outside the unit
// cube, as a normal, with frequency, and inside a pattern function. Each tile is a unit
// square at z = 0 (the pattern moved along z to pick a slice).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <2, 1.5, -5> look_at <2, 1.5, 0> right x * 4 up y * 3 }
light_source { <-2, 6, -8> color rgb 1 }
background { color rgb <0.1, 0.1, 0.2> }
#declare Map = color_map { [0 rgb <0, 0, 0.3>] [0.4 rgb <0.9, 0.3, 0.1>] [1 rgb <1, 1, 0.8>] }
#declare Density = function { pattern { density_file df3 "density_cloud16.df3" interpolate 2 } }
box { 0, <1, 1, 0.1>
    pigment { density_file df3 "density_cloud.df3" color_map { Map } translate z * -0.3 }
    finish { ambient 0.4 diffuse 0.6 } translate <0, 2, 0> }
box { 0, <1, 1, 0.1>
    pigment { density_file df3 "density_cloud.df3" interpolate 1 color_map { Map } translate z * -0.3 }
    finish { ambient 0.4 diffuse 0.6 } translate <1, 2, 0> }
box { 0, <1, 1, 0.1>
    pigment { density_file df3 "density_cloud.df3" interpolate 2 color_map { Map } translate z * -0.3 }
    finish { ambient 0.4 diffuse 0.6 } translate <2, 2, 0> }
box { 0, <1, 1, 0.1>
    pigment { density_file df3 "density_cloud" interpolate 11 color_map { Map } translate z * -0.55 }
    finish { ambient 0.4 diffuse 0.6 } translate <3, 2, 0> }
box { 0, <1, 1, 0.1>
    pigment { density_file df3 "density_cloud16.df3" interpolate 1 color_map { Map } translate z * -0.5 }
    finish { ambient 0.4 diffuse 0.6 } translate <0, 1, 0> }
box { 0, <1, 1, 0.1>
    pigment { density_file df3 "density_cloud16.df3" interpolate -1 color_map { Map } translate z * -0.1 }
    finish { ambient 0.4 diffuse 0.6 } translate <1, 1, 0> }
box { 0, <1, 1, 0.1>
    pigment { density_file df3 "density_cloud32.df3" color_map { Map } translate z * -0.5 }
    finish { ambient 0.4 diffuse 0.6 } translate <2, 1, 0> }
box { 0, <1, 1, 0.1>
    pigment { density_file df3 "density_cloud32.df3" interpolate 2 color_map { Map } translate z * -0.7 }
    finish { ambient 0.4 diffuse 0.6 } translate <3, 1, 0> }
box { 0, <1, 1, 0.1>
    pigment { density_file df3 "density_cloud.df3" interpolate 1 color_map { Map } scale 0.6 translate z * -0.3 }
    finish { ambient 0.4 diffuse 0.6 } translate <0, 0, 0> }
box { 0, <1, 1, 0.1>
    pigment { rgb <0.8, 0.8, 0.7> }
    normal { density_file df3 "density_cloud.df3" 1.5 interpolate 1 translate z * -0.3 }
    finish { ambient 0.4 diffuse 0.6 } translate <1, 0, 0> }
box { 0, <1, 1, 0.1>
    pigment { function { Density(x, y, z + 0.4) } color_map { Map } }
    finish { ambient 0.4 diffuse 0.6 } translate <2, 0, 0> }
box { 0, <1, 1, 0.1>
    pigment { density_file df3 "density_cloud.df3" interpolate 1 frequency 2 color_map { Map } translate z * -0.3 }
    finish { ambient 0.4 diffuse 0.6 } translate <3, 0, 0> }
