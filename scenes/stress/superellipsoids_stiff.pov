// Superellipsoids with POV-Ray's stiffest exponents (2/e up to 100: faces flat to 1e-30
// and edges sharp), tiny and huge scales, and rays grazing the flat faces.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.6, -9> look_at <0, 0, 0> angle 45 }
light_source { <10, 20, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
#declare Exps = array[5] { 0.02, 0.05, 0.1, 0.5, 4 }
#declare I = 0;
#while (I < 5)
  superellipsoid { <Exps[I], Exps[4 - I]>
    pigment { rgb <1, 0.6, 0.2> }
    scale 0.6 rotate <-5 * I, 10 * I, 0>
    translate <(I - 2) * 1.5, 0.9, 0> }
  #declare I = I + 1;
#end
// Edge-on flat faces, far and near, tiny and huge.
superellipsoid { <0.03, 0.03> pigment { rgb 1 } scale <3, 0.4, 1> translate <0, -1.4, 2> }
superellipsoid { <0.1, 0.05> pigment { rgb 0.7 } scale 1e-3 translate <0, -0.6, -8.99> }
superellipsoid { <0.05, 0.2> pigment { rgb 0.5 } scale 1e4 translate <0, -1.02e4, 3e4> }
