// mesh_camera, distribution 0: ray k of a pixel starts on face (row * width + column) of
// mesh k and leaves along the face's normal (here +z, each face a small triangle over
// its pixel: an orthographic view). Four meshes offset by a quarter pixel give four rays
// per pixel, averaged (supersampling). POV-Ray's shift to the pixel centre makes image
// rows 0 and 1 both take face row 0. location.z starts the rays that far along the
// normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare W = image_width;
#declare H = image_height;
#declare PW = 4 / W;
#declare PH = 3 / H;
#macro Grid(OX, OY)
  mesh {
    #local R = 0;
    #while (R < H)
      #local C = 0;
      #while (C < W)
        #local X = -2 + (C + OX) * PW;
        #local Y = 1.5 - (R + OY) * PH;
        triangle { <X, Y, 0>, <X, Y + PH * 0.5, 0>, <X + PW * 0.5, Y, 0> }
        #local C = C + 1;
      #end
      #local R = R + 1;
    #end
    rotate x * 20
    translate <0, 2.5, -6>
  }
#end
camera {
  mesh_camera { 4 0 Grid(0, 0) Grid(0.5, 0) Grid(0, 0.5) Grid(0.5, 0.5) }
  location <0, 0, 0.5>
}
light_source { <-4, 6, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
sphere { <-0.8, 0.7, 1>, 0.7 pigment { rgb <1, 0.4, 0.3> } finish { phong 0.6 } }
box { <0.4, 0, 0.5>, <1.4, 1.6, 1.5> rotate y * 30 pigment { rgb <0.3, 0.6, 1> } }
sphere { <1.6, 0.25, -0.8>, 0.25 pigment { rgb <1, 0.9, 0.3> } }
