// Coincident and near-coincident faces: boxes sharing a face, faces 1e-7 and 1e-5 apart, and a
// mesh whose triangles share edges (no seam may open between them).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <1, 2, -5> look_at <0, 0.5, 0> }
light_source { <5, 10, -10> rgb 1 }
background { rgb <0.2, 0.2, 0.2> }
box { <-2, 0, -1>, <-1, 1, 0> pigment { rgb <1, 0, 0> } }
box { <-2, 0, -1>, <-1, 1, 0> pigment { rgb <1, 0, 0> } }
box { <-0.5, 0, -1>, <0.5, 1, -1e-7> pigment { rgb <0, 1, 0> } }
box { <-0.5, 0, -1>, <0.5, 1, 0> pigment { rgb <0, 1, 0> } }
box { <1, 0, -1>, <2, 1, -1e-5> pigment { rgb <0, 0, 1> } }
box { <1, 0, -1>, <2, 1, 0> pigment { rgb <0, 0, 1> } }
mesh {
  triangle { <-2, -0.5, -2>, <0, -0.5, -2>, <0, 0, 1> }
  triangle { <0, -0.5, -2>, <2, -0.5, -2>, <0, 0, 1> }
  triangle { <-2, -0.5, -2>, <0, 0, 1>, <-2, 0, 1> }
  triangle { <2, -0.5, -2>, <2, 0, 1>, <0, 0, 1> }
  pigment { rgb <0.8, 0.8, 0.6> }
}
