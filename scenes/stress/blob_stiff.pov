// Blobs where their quartics are stiff: two spheres barely touching (a pinch whose
// field just passes the threshold), a blob seen at a tiny and a huge scale, many
// overlapping components with tiny and large strengths, a cylinder blob along its axis,
// and a threshold close to a component's peak (a flat maximum: near-double roots).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.32, -9> look_at <0, 0.3, 0> angle 45 }
light_source { <10, 20, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
blob { threshold 0.5
  sphere { <-0.7, 0, 0>, 1, 1 } sphere { <0.7, 0, 0>, 1, 1 }
  sturm translate <-2.6, 0.3, 0> pigment { rgb <1, 0.6, 0.2> } }
blob { threshold 0.999 sphere { 0, 1, 1 } sphere { <0.3, 0.2, 0>, 0.5, 1e-3 }
  translate <-0.8, 0.6, 0> pigment { rgb <1, 0.8, 0.4> } }
blob { threshold 0.6
  #declare I = 0;
  #while (I < 24)
    sphere { <sin(I * 1.3) * 0.8, cos(I * 2.1) * 0.6, sin(I * 0.7) * 0.5>,
             0.3 + mod(I, 5) * 0.15, (mod(I, 3) - 0.8) * 2 }
    #declare I = I + 1;
  #end
  rotate <20, 30, 0> translate <1.2, 0.3, 0> pigment { rgb <0.4, 0.8, 0.4> } }
blob { threshold 0.5 cylinder { <0, 0, -2>, <0, 0, 2>, 0.4, 1 } sphere { <0, 0, 1>, 0.5, -1 }
  rotate <0.3, 0.2, 0> translate <2.8, 0.32, 1> pigment { rgb 0.8 } }
blob { threshold 0.5 sphere { 0, 1, 1 } sphere { x, 1, 1 }
  scale 1e-3 rotate 2*x translate <0.3, 0.32, -8.99> pigment { rgb 0.7 } }
blob { threshold 0.5 sphere { 0, 1, 1 } cylinder { -x, x, 0.5, 1 }
  scale 1e3 rotate 0.01*x translate <0, 0.3, 5e3> pigment { rgb 0.5 } }
