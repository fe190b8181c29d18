// CSGs with many children (each walked through its box index, trace/csg_children.h):
// glass and filtering merges of spheres and of triangles (no insides), with a no_shadow,
// a clipped and a bounded_by child; an inverse intersection and an inverse difference
// (POV-Ray merges of inverted and of plain children) clipped to boxes; a glass box minus
// twenty cylinders; merges nested in a merge, one with a plane.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }
camera { location <0, 2.6, -5.5> look_at <0, 0.1, 0.3> angle 62 }
light_source { <-4, 8, -5> color rgb 1 }
light_source { <5, 4, -3> color rgb 0.35 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1, 0.3, 0.6> scale 0.5 } }

#declare I = 0;
merge {
  #while (I < 24)
    sphere { <cos(I * 0.7) * 0.6, 0.25 * sin(I * 1.3), sin(I * 0.7) * 0.6>, 0.3 + 0.1 * sin(I) }
    #declare I = I + 1;
  #end
  cylinder { <-0.8, -0.5, 0>, <0.8, -0.5, 0>, 0.15 no_shadow }
  box { -0.3, 0.3 rotate 45 * y translate <0, 0.55, 0> clipped_by { sphere { <0, 0.55, 0>, 0.4 } } }
  torus { 0.75, 0.1 bounded_by { box { <-0.9, -0.2, -0.9>, <0.9, 0.2, 0.9> } } translate y * 0.1 }
  pigment { rgbf <0.8, 1, 0.9, 0.85> } interior { ior 1.4 } translate <-2.4, 0.2, 0>
}

#declare I = 0;
merge {
  #while (I < 40)
    #declare C = <sin(I * 2.1) * 0.7, 0.6 + 0.6 * sin(I * 0.9), cos(I * 1.7) * 0.5>;
    triangle { C + <-0.3, -0.2, 0.1 * sin(I)>, C + <0.3, -0.15, 0.2>, C + <0, 0.3, -0.2> }
    #declare I = I + 1;
  #end
  sphere { <0, 0.4, 0>, 0.35 }
  sphere { <0.3, 0.8, 0>, 0.25 }
  pigment { rgbf <1, 0.7, 0.5, 0.6> } finish { specular 0.4 } translate <0, 0, -0.5>
}

#declare I = 0;
intersection {
  #while (I < 18)
    sphere { <0.25 * cos(I), 0.2 * sin(I * 1.7), 0.25 * sin(I)>, 0.6 }
    #declare I = I + 1;
  #end
  triangle { <-1, 0, -1>, <1, 0, -1>, <0, 0.5, 1> }
  inverse
  clipped_by { box { <-0.9, -0.9, -0.9>, <0.9, 0.9, 0.9> } }
  pigment { rgbt <0.6, 0.8, 1, 0.5> } interior { ior 1.2 } translate <2.4, 0.1, 0.3>
}

#declare I = 0;
difference {
  box { -0.5, 0.5 }
  #while (I < 16)
    sphere { <0.8 * cos(I * 0.4), 0.5 * sin(I * 0.8), 0.8 * sin(I * 0.4)>, 0.25 }
    #declare I = I + 1;
  #end
  inverse
  clipped_by { sphere { 0, 0.95 } }
  pigment { rgbf <1, 0.9, 0.6, 0.5> } translate <1.2, -0.3, 2>
}

#declare I = 0;
difference {
  box { <-0.6, -0.6, -0.3>, <0.6, 0.6, 0.3> }
  #while (I < 20)
    cylinder { <-0.55 + 0.06 * I, -0.7, -0.4 + 0.04 * I>, <-0.5 + 0.05 * I, 0.7, 0.35>, 0.04 }
    #declare I = I + 1;
  #end
  pigment { rgbt <0.9, 1, 0.8, 0.7> } interior { ior 1.5 } rotate y * 20 translate <-1.3, -0.3, 2>
}

#declare I = 0;
merge {
  #while (I < 16)
    merge {
      sphere { <0.15 * I - 1.1, 0, 0>, 0.16 }
      sphere { <0.15 * I - 1.1, 0.15, 0>, 0.12 }
      #declare J = 0;
      #while (J < 16)
        sphere { <0.15 * I - 1.1, 0.2 + 0.03 * J, 0.02 * J>, 0.03 }
        #declare J = J + 1;
      #end
    }
    #declare I = I + 1;
  #end
  plane { z, 0.1 clipped_by { box { <-1.3, -0.2, -1>, <1.3, 0.2, 1> } } }
  pigment { rgbf <0.7, 0.9, 1, 0.7> } interior { ior 1.3 } translate <0, -0.7, -2.3>
}

// A sphere minus a union of many (the union held inverted by the difference), one part of
// it clipped; an intersection of sixteen turned boxes.
#declare I = 0;
difference {
  sphere { 0, 0.7 }
  union {
    #while (I < 30)
      sphere { 0.7 * <cos(I * 0.9) * cos(I * 0.37), sin(I * 0.37), sin(I * 0.9) * cos(I * 0.37)>, 0.18 }
      #declare I = I + 1;
    #end
    cylinder { -y, y, 0.12 clipped_by { plane { x, 0.05 } } }
  }
  pigment { rgbf <1, 0.8, 0.8, 0.6> } interior { ior 1.3 } translate <2.2, 0.6, -1.4>
}

#declare I = 0;
intersection {
  #while (I < 16)
    box { -0.5, 0.5 rotate <I * 11, I * 23, I * 7> }
    #declare I = I + 1;
  #end
  pigment { rgbt <0.5, 1, 0.7, 0.4> } translate <-2.4, 0.4, -1.6>
}
