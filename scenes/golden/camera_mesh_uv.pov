// mesh_camera, distribution 3 (texture baking): a pixel's ray starts at the point of
// the first mesh whose uv coordinates are the pixel's, (column / width, 1 - row /
// height), found through POV-Ray's tenths-of-u-and-v index; `smooth` takes the normal
// there from the vertex normals (here fanned out: a wide view from a flat grid). A
// pixel whose uv no face covers (the corner cut off) has no ray: transparent black.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare N = 12;
#macro P(I, J) <-1.5 + 3 * I / N, 1.2 - 2.4 * J / N, 0> #end
#macro Nr(I, J) <(I / N - 0.5) * 1.2, (0.5 - J / N) * 0.9, 1> #end
#macro UV(I, J) <I / N, 1 - J / N> #end
camera {
  mesh_camera { 1 3
    mesh {
      #local J = 0;
      #while (J < N)
        #local I = 0;
        #while (I < N)
          #if (I + J < 2 * N - 3)
            smooth_triangle { P(I, J), Nr(I, J), P(I + 1, J), Nr(I + 1, J),
              P(I, J + 1), Nr(I, J + 1)
              uv_vectors UV(I, J), UV(I + 1, J), UV(I, J + 1) }
            smooth_triangle { P(I + 1, J), Nr(I + 1, J), P(I + 1, J + 1),
              Nr(I + 1, J + 1), P(I, J + 1), Nr(I, J + 1)
              uv_vectors UV(I + 1, J), UV(I + 1, J + 1), UV(I, J + 1) }
          #end
          #local I = I + 1;
        #end
        #local J = J + 1;
      #end
      translate <0, 1, -5>
    }
    smooth
  }
}
light_source { <-4, 6, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
sphere { <-0.8, 0.7, 1>, 0.7 pigment { rgb <1, 0.4, 0.3> } finish { phong 0.6 } }
box { <0.4, 0, 0.5>, <1.4, 1.6, 1.5> rotate y * 30 pigment { rgb <0.3, 0.6, 1> } }
