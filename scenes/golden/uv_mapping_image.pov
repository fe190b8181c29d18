// uv_mapping with an image_map on every shape POV-Ray 3.7 gives surface coordinates:
// sphere, box (its cube layout), torus, lathe, sor (curve and both caps), ovus and
// bicubic_patch (with uv_vectors), turned and scaled so that the object's transforms
// (which move the coordinates with the surface) are exercised; a cylinder and a disc have
// none of their own and show the world point's x and y.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -14> look_at <0, 0.3, 0> angle 50 }
light_source { <-10, 20, -20> color rgb 1 }
#declare Card = pigment { uv_mapping image_map { png "images/card.png" } }
#declare Lit = finish { ambient 0.35 diffuse 0.65 }
sphere { 0, 1.2 pigment { Card } finish { Lit } rotate <20, -30, 0> translate <-4, 1.2, 2> }
box { <-1, -1, -1>, <1, 1, 1> pigment { Card } finish { Lit }
      rotate <-25, 35, 0> translate <0, 1.2, 2.5> }
torus { 1, 0.45 pigment { Card } finish { Lit } rotate <-60, 0, 0> scale 1.1
        translate <4, 1.3, 2> }
lathe { cubic_spline 6, <0, -1>, <0.6, -1>, <1, -0.3>, <0.5, 0.6>, <0.8, 1.2>, <0.8, 1.5>
        pigment { Card } finish { Lit } rotate -20 * x translate <-4.2, 0.1, -2.3> }
sor { 5, <0, -0.1>, <0.9, 0>, <0.5, 0.8>, <0.9, 1.6>, <0.5, 1.7>
      pigment { Card } finish { Lit } rotate <-40, 20, 0> scale 1.2 translate <-1.5, 0.2, -2.5> }
ovus { 1, 0.6 pigment { Card } finish { Lit } rotate <0, 60, -15> translate <1.3, 0, -2.8> }
bicubic_patch { type 1 flatness 0 u_steps 3 v_steps 3
  uv_vectors <0, 0>, <2, 0>, <2, 1.5>, <0, 1.5>
  <0, 0, 0>, <1, 0.5, 0>, <2, 0.5, 0>, <3, 0, 0>,
  <0, 0.5, 1>, <1, 1.5, 1>, <2, 1.5, 1>, <3, 0.5, 1>,
  <0, 0.5, 2>, <1, 1.5, 2>, <2, 1.5, 2>, <3, 0.5, 2>,
  <0, 0, 3>, <1, 0.5, 3>, <2, 0.5, 3>, <3, 0, 3>
  pigment { Card } finish { Lit } rotate <-70, 0, 0> scale 0.8 translate <3.2, -0.8, -2> }
cylinder { <-6.5, -1, 0>, <-6.5, 2, 0>, 0.6 pigment { Card scale 2 } finish { Lit } }
disc { <6.5, 0.5, 0>, <-1, 0.3, -1>, 0.9 pigment { Card } finish { Lit } }
plane { y, -1.2 pigment { checker rgb 0.8 rgb 0.5 } }
