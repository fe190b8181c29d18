// Slivers and near-degenerate triangles: aspect ratios to 1e-8, a fan of needles meeting at one
// vertex, and a triangle seen exactly edge-on.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -3> look_at <0, 0, 0> }
light_source { <2, 5, -10> rgb 1 }
background { rgb <0.1, 0.1, 0.15> }
triangle { <-1.5, 0.5, 0>, <1.5, 0.5, 0>, <0, 0.5 + 1e-8, 0> pigment { rgb 1 } }
triangle { <-1.5, 0.3, 0>, <1.5, 0.3 + 1e-3, 0>, <1.5, 0.3 + 2e-3, 0> pigment { rgb <1, 0.5, 0> } }
mesh {
  #declare I = 0;
  #while (I < 24)
    triangle { <0, -0.6, 0>, <cos(I * pi / 12), -0.6 + sin(I * pi / 12), 0.2>,
               <cos((I + 0.002) * pi / 12), -0.6 + sin((I + 0.002) * pi / 12), 0.2> }
    #declare I = I + 1;
  #end
  pigment { rgb <0.4, 1, 0.4> }
}
triangle { <-1, -1.2, 0>, <1, -1.2, 0>, <0, -1.2, 1> pigment { rgb <0.4, 0.4, 1> } translate <0, 0, 0> }
polygon { 5, <-1.4, 0.8>, <1.4, 0.8>, <1.4, 0.8 + 1e-6>, <-1.4, 0.8 + 1e-6>, <-1.4, 0.8>
  pigment { rgb <1, 0.2, 0.2> } }
