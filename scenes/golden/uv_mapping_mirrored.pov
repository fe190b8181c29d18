// uv_mapping on mirrored objects: a box mirrored by negative scales (POV-Ray mirrors its
// corners, so its coordinates flip with it) and a sphere and a torus mirrored and turned
// (their coordinates come from their own space).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -10> look_at <0, 0.5, 0> angle 50 }
light_source { <-10, 20, -20> color rgb 1 }
#declare Card = pigment { uv_mapping image_map { png "images/card.png" } }
#declare Lit = finish { ambient 0.35 diffuse 0.65 }
box { <-1, -1, -1>, <1, 1, 1> pigment { Card } finish { Lit } scale <-1.2, 1, 1> translate <-3, 1.2, 0> }
box { <-1, -1, -1>, <1, 1, 1> pigment { Card } finish { Lit } scale <1, -1.2, -1> translate <0, 1.2, 0> }
box { <-1, -1, -1>, <1, 1, 1> pigment { Card } finish { Lit } scale <-1, 1, -0.8> translate <3, 1.2, 0> }
sphere { 0, 1 pigment { Card } finish { Lit } scale -1 rotate 30 * y translate <-3, -1.5, 0> }
sphere { 0, 1 pigment { Card } finish { Lit } scale <1, -1, 1> rotate 30 * y translate <0, -1.5, 0> }
torus { 0.8, 0.3 pigment { Card } finish { Lit } scale <-1, 1, 1> rotate -60 * x translate <3, -1.5, 0> }
