// Large CSGs as exporters write them: a see-through merge of 2,000 triangles (a molecular
// surface written as one merge) and an OpenSCAD-style plate minus 400 drilled holes,
// both glass. POV-Ray tests every child of a CSG for each ray, and every sibling's inside
// for each crossing; povwall's child index (trace/csg_children.h) asks only those whose
// boxes the ray or the point reach.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 3, -6> look_at <0, 0, 0> angle 50 }
light_source { <5, 10, -10> color rgb 1 }
background { color rgb <0.2, 0.3, 0.4> }
plane { y, -1.5 pigment { checker color rgb 1 color rgb 0.1 } }

#declare R = seed(7);
merge {
  #declare I = 0;
  #while (I < 2000)
    #declare C = <rand(R) * 3 - 1.5, rand(R) * 2 - 1, rand(R) * 2 - 1>;
    triangle { C, C + <rand(R), rand(R), rand(R)> * 0.4 - 0.2, C + <rand(R), rand(R), rand(R)> * 0.4 - 0.2 }
    #declare I = I + 1;
  #end
  pigment { rgbf <1, 0.8, 0.6, 0.7> } finish { specular 0.3 } translate <-1.6, 0.3, 0>
}

difference {
  box { <-1.5, -0.2, -1.5>, <1.5, 0.2, 1.5> }
  #declare I = 0;
  #while (I < 400)
    cylinder { <-1.4 + 0.14 * mod(I, 20) + 0.07, -0.3, -1.4 + 0.14 * floor(I / 20) + 0.07>,
               <-1.4 + 0.14 * mod(I, 20) + 0.07, 0.3, -1.4 + 0.14 * floor(I / 20) + 0.07>, 0.05 }
    #declare I = I + 1;
  #end
  pigment { rgbf <0.9, 1, 0.9, 0.8> } interior { ior 1.4 } rotate x * -20 translate <1.6, -0.4, 0.5>
}
