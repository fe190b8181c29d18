// golden-args: --block-mean 8 --max-rmse 0.03 --fail 0.045 --max-bad-fraction 0
// Radiosity indoors: a Cornell-like box (red and green walls, white floor, ceiling and
// back) lit by one point light below the ceiling; the walls bleed their colours onto
// the floor and the two blocks, and the shadowed sides are lit by bounced light only.
// Default radiosity settings (two bounces), ambient ignored (#version 3.7).
#version 3.7;
global_settings { assumed_gamma 1.0 radiosity { } }
camera { location <0, 1, -0.98> look_at <0, 0.9, 0> angle 75 }
light_source { <0, 1.9, -0.3> color rgb 1 }
#declare White = finish { diffuse 0.8 ambient 0.3 };
box { <-1, 0, -1>, <1, 2, 1> inverse pigment { rgb 0.9 } finish { White } }
box { <-1.01, -0.01, -1>, <-0.999, 2.01, 1> pigment { rgb <0.8, 0.1, 0.1> } finish { White } }
box { <0.999, -0.01, -1>, <1.01, 2.01, 1> pigment { rgb <0.1, 0.7, 0.1> } finish { White } }
box { <-0.3, 0, -0.3>, <0.3, 1.2, 0.3> rotate y * 20 translate <-0.35, 0, 0.3>
      pigment { rgb 0.9 } finish { White } }
box { <-0.3, 0, -0.3>, <0.3, 0.6, 0.3> rotate y * -20 translate <0.4, 0, -0.3>
      pigment { rgb 0.9 } finish { White } }
