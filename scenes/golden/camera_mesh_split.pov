// mesh_camera, distribution 1: the meshes' faces one after the other, face (row *
// width + column) for a pixel, here the top half from the first mesh and the bottom
// half from the second (a second ray per pixel would start at face index + all faces:
// never a face, so POV-Ray averages the first ray alone). The faces' normals point to
// -z; a negative direction.z turns the rays around. Pixels past the faces have no ray:
// transparent black.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare W = image_width;
#declare H = image_height;
#declare PW = 4 / W;
#declare PH = 3 / H;
#macro Rows(R0, R1)
  mesh {
    #local R = R0;
    #while (R < R1)
      #local C = 0;
      #while (C < W)
        #local X = -2 + C * PW;
        #local Y = 1.5 - R * PH;
        triangle { <X, Y, 0>, <X + PW * 0.5, Y, 0>, <X, Y + PH * 0.5, 0> }
        #local C = C + 1;
      #end
      #local R = R + 1;
    #end
  }
#end
#declare Top = Rows(0, int(H / 2))
#declare Bottom = Rows(int(H / 2), H - 6)
camera {
  mesh_camera { 2 1
    mesh { Top translate <0, 1, -6> }
    mesh { Bottom scale <1, 1.1, 1> translate <0.2, 1, -6> }
  }
  direction <0, 0, -1>
}
light_source { <-4, 6, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
sphere { <-0.8, 0.7, 1>, 0.7 pigment { rgb <1, 0.4, 0.3> } finish { phong 0.6 } }
box { <0.4, 0, 0.5>, <1.4, 1.6, 1.5> rotate y * 30 pigment { rgb <0.3, 0.6, 1> } }
