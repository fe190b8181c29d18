// POV-Ray checks a smooth_triangle again after each transform: normals that a shear or a
// non-uniform scale turns across the moved face make it degenerate (never hit), and it
// stays so when a later transform undoes the first. A mesh's smooth faces are not checked
// again (the mesh keeps its transform). Top, left to right: as written; sheared (gone); in
// a sheared union (gone); sheared and sheared back (gone); a mesh with the same face,
// sheared (seen). Below: turned and scaled uniformly (seen); scaled <1, 3, 0.2> (gone).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.5, -7> look_at <0, 0, 0> angle 60 }
light_source { <-3, 6, -8> color rgb 1 }
light_source { <4, 2, -5> color rgb 0.4 }
plane { z, 1.5 pigment { checker color rgb 0.85 color rgb <0.3, 0.45, 0.7> scale 0.5 } }
#declare Face = smooth_triangle {
  <0.816, -0.899, -0.668>, <0.033, 0.619, -0.042>, <0.685, 0.037, 0.93>, <0.304, 0.349, 0.126>,
  <-0.8, 0.604, 0.042>, <-0.983, 0.169, -0.988> }
#declare Shear = transform { matrix <1, 0, 0, 0.196, 1, 0, -0.444, 0, 1, 0.006, -0.166, 0.096> }
#declare Tex = texture { pigment { color rgb <0.9, 0.6, 0.3> } finish { phong 0.6 } }
object { Face texture { Tex } translate <-4, 1, 0> }
object { Face transform { Shear } texture { Tex } translate <-2.4, 1, 0> }
union { object { Face } transform { Shear } texture { Tex } translate <-0.8, 1, 0> }
object { Face transform { Shear } transform { Shear inverse } texture { Tex } translate <0.8, 1, 0> }
mesh { smooth_triangle {
  <0.816, -0.899, -0.668>, <0.033, 0.619, -0.042>, <0.685, 0.037, 0.93>, <0.304, 0.349, 0.126>,
  <-0.8, 0.604, 0.042>, <-0.983, 0.169, -0.988> }
  transform { Shear } texture { Tex } translate <2.4, 1, 0> }
object { Face rotate <20, 40, 10> scale 1.2 texture { Tex } translate <-2, -1.2, 0> }
object { Face scale <1, 3, 0.2> texture { Tex } translate <1, -1.2, 0> }
