// Macro arguments with no comma between bare number identifiers (a public flask macro
// called `flask(..., topHeight, bottomRoundness bottomCylRoundness bottomRadius, ...)`):
// POV-Ray 3.7 passes such an argument by reference to the identifier it looked ahead to,
// so Three(P Q R) binds A to Q, B to R and C to R (spheres at x = 0, 1, 1). An identifier
// followed by a literal, a comma or an operator is passed as itself.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -5> look_at 0 right 4 * x up 3 * y }
light_source { <0, 0, -10> rgb 1 }
#declare P = -1;
#declare Q = 0;
#declare R = 1;
#declare V = <0, 0.8, 0>;
#macro Three(A B C)
  sphere { <A, 0, 0>, 0.4 pigment { rgb <1, 0, 0> } }
  sphere { <B, 0, 0>, 0.3 pigment { rgb <0, 1, 0> } }
  sphere { <C, 0, 0>, 0.2 pigment { rgb <0, 0, 1> } }
#end
#macro Two(A B)
  sphere { <A, -1, 0>, 0.3 pigment { rgb <1, 1, 0> } }
  sphere { <B, 0, 0> - V, 0.2 pigment { rgb <0, 1, 1> } }
#end
Three(P Q R)
Two(P 1)
Two(R 0.5)
