// Map entries: a texture_map with `average` shades every entry and weights each by its
// value (shadows too), and a normal_map entry starts from the #default normal (its bump
// size).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -31> right x * 4/3 direction 3 * z look_at 0 }
light_source { <200, 200, -100> color rgb 1 }
plane { z, 1.5 pigment { rgb 0.8 } }
box { <-1.5, -2, 0>, <6, 2, 1>
      texture { average texture_map {
        [1 pigment { rgb <1, 0, 0> } finish { ambient 0 diffuse 1 }]
        [2 pigment { rgbt <0, 0, 1, 0.5> } finish { ambient 0 diffuse 0.6 specular 0.8 }]
        [1 pigment { checker rgb 1 rgb 0 scale 0.5 } finish { ambient 0.2 diffuse 0.5 }] } } }
sphere { <3, 0, -3>, 1 texture { average texture_map { [1 pigment { rgbf <1, 1, 1, 0.9> }] [1 pigment { rgb 1 }] } } }
#default { normal { bump_size 1.5 } }
box { <-6, -2, 0>, <-2, 2, 1> pigment { rgb 1 } finish { phong 0.8 phong_size 200 }
      normal { gradient y normal_map { [0 gradient x triangle_wave scale 0.3]
                                       [1 gradient x triangle_wave scale 0.3] } } }
