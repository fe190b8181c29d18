// mesh_camera, distribution 2: the meshes side by side across the image, one ray per
// pixel; the face index counts the column from the image's left edge (as POV-Ray's
// does), so the right mesh's pixels take faces further along its rows. The left mesh
// is turned: its rays turn with its normals (transformed as normals).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare W = image_width;
#declare H = image_height;
#declare PW = 4 / W;
#declare PH = 3 / H;
#declare Half = mesh {
  #local R = 0;
  #while (R < H)
    #local C = 0;
    #while (C < W)
      #local X = -2 + C * PW;
      #local Y = 1.5 - R * PH;
      triangle { <X, Y, 0>, <X, Y + PH * 0.5, 0>, <X + PW * 0.5, Y, 0> }
      #local C = C + 1;
    #end
    #local R = R + 1;
  #end
}
camera {
  mesh_camera { 1 2
    mesh { Half rotate <10, -15, 0> translate <0, 1, -6> }
    mesh { Half translate <0, 1, -6> }
  }
}
light_source { <-4, 6, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
sphere { <-0.8, 0.7, 1>, 0.7 pigment { rgb <1, 0.4, 0.3> } finish { phong 0.6 } }
box { <0.4, 0, 0.5>, <1.4, 1.6, 1.5> rotate y * 30 pigment { rgb <0.3, 0.6, 1> } }
