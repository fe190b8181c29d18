// Thin and fat tori (minor/major from 1e-4 to 0.999) seen at grazing angles: the quartic's
// roots come in close pairs (thin) or nearly coincide at the hole (fat).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.08, -7> look_at <0, 0, 0> angle 40 }
light_source { <10, 20, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
#declare Ratios = array[6] { 1e-4, 1e-3, 1e-2, 0.1, 0.5, 0.999 }
#declare I = 0;
#while (I < 6)
  torus { 1, Ratios[I] * 1
    pigment { rgb <1, 0.6, 0.2> }
    rotate <0.5 * I, 0, 0>
    translate <(I - 2.5) * 1.1, 0, I * 0.7> }
  #declare I = I + 1;
#end
// A thin torus almost edge-on, filling the view.
torus { 2.5, 1e-3 pigment { rgb 1 } rotate <0.2, 0, 0> translate <0, -0.3, 2> }
