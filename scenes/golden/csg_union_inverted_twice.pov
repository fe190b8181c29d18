// POV-Ray inverts a CSG by morphing it (a union or a merge into an intersection, an
// intersection into a merge), so a union inverted twice is a merge: here a union subtracted
// inside a difference that is itself subtracted (found by a random scene: the camera inside a
// superellipsoid sees the mesh triangle cut by the merge, not by a union).
#version 3.7;
global_settings { assumed_gamma 1 }
light_source { <0.5, 0.3, -0.2> rgb 1 }
difference {
  superellipsoid { <0.501, 0.759> }
  difference {
    mesh { triangle { <0, 1, 0>, <0.9, -0.5, -0.5>, <0, -0.5, 0.9> } }
    union {
      superellipsoid { <0.965, 1.219> }
      sphere_sweep { linear_spline 4, <-0.262, -0.439, 0.779>, 0.28, <0.749, 0.163, 0.431>, 0.178,
                     <0.46, 0.307, 0.098>, 0.176, <0.391, -0.575, -0.777>, 0.287 }
    }
  }
  pigment { image_map { png "images/card.png" map_type 0 } translate -0.5 scale 0.5 }
}
