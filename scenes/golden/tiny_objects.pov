// Objects near the float spacing of their coordinates (about 1.2e-7 at x = 1.3): POV-Ray
// keeps bounding boxes in single precision and meets them in single precision, so such
// objects lose parts or vanish (trace/pov_bounds.h). Left: a Pythagoras tree of boxes
// 0.00002 thick, 12 levels, the deepest about 1e-7 across. Right: a 4x4 block of each
// shape, 5e-7 across: axis-aligned and rotated boxes, a sphere (too small for POV-Ray's
// sphere test: never hit), an ellipsoid, cylinders, cones, discs, triangles, a mesh, a
// polygon made at unit size and one made tiny (degenerate: never hit), a torus scaled
// down and one made tiny (POV-Ray's root elimination: shaded at the cubic's roots), a CSG
// intersection and a clipped union. The plane behind takes their shadows.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare P = <1.3, 0.7, 0.4>;
#declare W = 6e-5;  // width of the view
camera {
  location P + <0.5 * W, 0.36 * W, -0.02>
  look_at P + <0.5 * W, 0.36 * W, 0>
  angle degrees(atan2(W, 0.02))
}
light_source { <-3, 6, -8> rgb 1 }
light_source { <4, 2, -8> rgb 0.5 }
plane { z, P.z + 2e-6 pigment { rgb <0.4, 0.6, 0.3> } }

#declare C = sqrt(0.5);
#macro Tree(N)
  union {
    box { <0, 0, 0>, <1, 1, 0.00002> }
    #if (N > 0)
      object { Tree(N - 1) scale C rotate 45 * z translate <0, 1, 0> }
      object { Tree(N - 1) translate <-1, 0, 0> scale C rotate -45 * z translate <1, 1, 0> }
    #end
  }
#end
object { Tree(12) pigment { rgb <0.8, 0.5, 0.2> } scale 5.5e-6 translate P + <0.25 * W, 0.02 * W, 0> }

#declare S = 5e-7;
#macro Block(Obj, Col, Row)
  #for (I, 0, 3)
    #for (J, 0, 3)
      object { Obj translate P + <(0.63 + 0.09 * Col) * W + I * 1.13e-6, (0.04 + 0.17 * Row) * W + J * 1.07e-6, 0> }
    #end
  #end
#end
Block(box { 0, S pigment { rgb <0.9, 0.5, 0.2> } }, 0, 0)
Block(box { 0, S rotate <20, 30, 10> pigment { rgb <0.5, 0.9, 0.9> } }, 1, 0)
Block(sphere { 0, 0.5 * S pigment { rgb 1 } }, 2, 0)
Block(sphere { 0, 1 scale <0.5, 0.3, 0.4> * S pigment { rgb <0.9, 0.9, 0.5> } }, 3, 0)
Block(cylinder { 0, <S, S, 0>, 0.3 * S pigment { rgb <0.2, 0.6, 0.9> } }, 0, 1)
Block(cone { 0, 0.5 * S, <0, S, 0>, 0.1 * S pigment { rgb <0.9, 0.9, 0.2> } }, 1, 1)
Block(disc { 0, <0.3, 0.2, -1>, 0.5 * S pigment { rgb <0.9, 0.2, 0.9> } }, 2, 1)
Block(triangle { 0, <S, 0, 0>, <0, S, 0> pigment { rgb <0.2, 0.9, 0.2> } }, 3, 1)
Block(mesh { triangle { 0, <S, 0, 0>, <0, S, 0> } triangle { <S, 0, 0>, <S, S, 0>, <0, S, 0> }
             pigment { rgb <0.6, 0.6, 0.9> } }, 0, 2)
Block(polygon { 4, 0, x, x + y, y scale S pigment { rgb <0.3, 0.3, 0.9> } }, 1, 2)
Block(polygon { 4, 0, <S, 0, 0>, <S, S, 0>, <0, S, 0> pigment { rgb 1 } }, 2, 2)
Block(torus { 1, 0.4 rotate 90 * x scale 0.4 * S pigment { rgb <0.9, 0.4, 0.4> } }, 3, 2)
Block(torus { 0.4 * S, 0.15 * S rotate 90 * x pigment { rgb <0.9, 0.2, 0.2> } }, 0, 3)
Block(intersection { box { 0, S } sphere { 0, 1.2 * S } pigment { rgb <0.9, 0.6, 0.6> } }, 1, 3)
Block(union { box { 0, S } cylinder { 0, <0, 0, S>, 0.3 * S } clipped_by { box { 0, 0.8 * S } }
              pigment { rgb <0.7, 0.4, 0.1> } }, 2, 3)
Block(triangle { 0, <S, 0.3 * S, 0>, <0.2 * S, S, 0> rotate <0, 40, 0> pigment { rgb <0.5, 1, 0.5> } }, 3, 3)
