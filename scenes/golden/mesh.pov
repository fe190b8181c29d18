// mesh of smooth triangles built by a #while loop, a mesh2 with normal_vectors and one
// whose normal_indices pick its normals per corner.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0.5, 0> angle 50 }
light_source { <-3, 6, -4> color rgb 1 }
background { color rgb 0.2 }
#declare N = 12;
mesh {
  #declare I = 0;
  #while (I < N)
    #declare A0 = I * 360 / N; #declare A1 = (I + 1) * 360 / N;
    #declare P0 = vrotate(<1, 0, 0>, y * A0); #declare P1 = vrotate(<1, 0, 0>, y * A1);
    smooth_triangle { P0, P0, P1, P1, <0, 1.2, 0>, y }
    smooth_triangle { P0, P0, P1, P1, <0, -1, 0>, -y }
    #declare I = I + 1;
  #end
  pigment { color rgb <0.9, 0.7, 0.3> } finish { phong 0.6 }
  translate y * 0.8
}
mesh2 {
  vertex_vectors { 4, <-3, 0, 2>, <-1, 0, 2>, <-1, 0, 0>, <-3, 1, 0> }
  normal_vectors { 4, <0, 1, 0>, <0.3, 1, 0>, <0, 1, -0.3>, <0, 1, 0.2> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  pigment { color rgb <0.3, 0.8, 0.9> }
}
mesh2 {
  vertex_vectors { 4, <1, 0, 2>, <3, 0, 2>, <3, 0, 0>, <1, 1, 0> }
  normal_vectors { 3, <0, 1, 0>, <0.5, 1, 0>, <-0.4, 1, -0.4> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  normal_indices { 2, <1, 0, 2>, <2, 2, 1> }
  pigment { color rgb <0.9, 0.5, 0.8> } finish { phong 0.5 }
}
