// POV-Ray's triangle moves its corners at each transform and recomputes itself: the
// normal comes from the corners as they stand, then the first two are swapped when they
// wind the wrong way along the normal's largest component. So which face shows the
// interior_texture depends on the transforms after the corners (one, several, mirrored,
// from a CSG or an object wrapper), not only on the written order.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -12> look_at 0 angle 64 }
light_source { <3, 6, -10> rgb 1 }
light_source { <-6, -4, -10> rgb 0.5 }
background { rgb <0.2, 0.2, 0.25> }
#declare Tex = texture { pigment { rgb <0.55, 0.6, 0.62> } finish { ambient 0.2 } }
#declare Inner = texture { pigment { rgb <1, 0.1, 0.05> } finish { ambient 0.2 } }
#macro Tri(A, B, C)
  triangle { A, B, C texture { Tex } interior_texture { Inner } }
#end
#declare P1 = <-0.9, -0.8, 0.3>;
#declare P2 = <0.9, -0.3, 0>;
#declare P3 = <0.2, 0.9, -0.4>;
#declare Q1 = <-0.9, -0.8, 0.3>;
#declare Q2 = <0.2, 0.9, -0.4>;
#declare Q3 = <0.9, -0.3, 0>;
// Row 1: no transform; one translate; a union moved twice; a mirror.
#declare R1 = <-6, 3, 0>;
#declare R2 = <-3.8, 3, 0>;
Tri(P1 + R1, P2 + R1, P3 + R1)
Tri(Q1 + R2, Q2 + R2, Q3 + R2)
union { Tri(P1, P2, P3) Tri(Q1 + x * 2.3, Q2 + x * 2.3, Q3 + x * 2.3)
  translate <-1.5, 3, 1> translate -z }
object { Tri(P1, P2, P3) scale <-1, 1, 1> translate <3.5, 3, 0> }
object { Tri(Q1, Q2, Q3) scale <-1, 1, 1> translate <5.8, 3, 0> }
// Row 2: rotations that change the dominant axis, step by step.
object { Tri(P1, P2, P3) rotate 50 * y translate <-6, 0.8, 0> }
object { Tri(Q1, Q2, Q3) rotate 50 * y translate <-3.8, 0.8, 0> }
object { Tri(P1, P2, P3) rotate 50 * x rotate 120 * y translate <-1.5, 0.8, 0> }
object { Tri(Q1, Q2, Q3) rotate 50 * x rotate 120 * y translate <0.8, 0.8, 0> }
object { Tri(P1, P2, P3) rotate <50, 120, 0> translate <3.5, 0.8, 0> }
object { Tri(Q1, Q2, Q3) matrix <0, 0, 1, 0, 1, 0, -1, 0, 0, 0, 0, 0> translate <5.8, 0.8, 0> }
// Row 3: the camera far below, other turns, a declared triangle moved twice, scales.
#declare T = triangle { P1, P2, P3 texture { Tex } interior_texture { Inner } rotate 120 * z }
object { T translate <-6, -2.6, 0> }
object { T rotate 150 * x translate <-3.8, -2.6, 0> }
object { T scale <1, -1, 1> rotate 40 * y translate <-1.5, -2.6, 0> }
object { Tri(Q1, Q2, Q3) scale <1, 1, -1> rotate -60 * x translate <0.8, -2.6, 0> }
object { Tri(P1, P2, P3) rotate 200 * y translate <3.5, -2.6, 0> }
object { Tri(Q1, Q2, Q3) rotate 200 * y scale 1.1 translate <5.8, -2.6, 0> }
