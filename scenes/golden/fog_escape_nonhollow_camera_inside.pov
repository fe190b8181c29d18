// Ground fog and a camera inside solid objects: the camera is under a transparent solid
// plane and inside a hollow sphere, so its rays are not hollow (POV-Ray gives them the
// containing interiors) until they cross the plane: rays that stay below it show the
// background and the boxes unfogged, rays that cross it are fogged from there on.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 1, -10> look_at <0, 2.5, 0> angle 75 }
light_source { <-20, 300, -40> color rgb 1 }
background { rgb <0.3, 0.5, 0.9> }
fog { fog_type 2 distance 8 color rgb <0.9, 0.8, 0.7> fog_offset 0.5 fog_alt 2 up y }
plane { y, 3 pigment { rgbt <1, 1, 1, 0.85> } finish { ambient 0.1 diffuse 0 } }
sphere { <0, 1, -10>, 1 hollow pigment { rgbt <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0 } }
box { <-6, -2, 5>, <-3, 1, 8> pigment { checker rgb 0.9 rgb <0.6, 0.1, 0.1> } }
box { <3, 0, 15>, <6, 2.5, 18> pigment { checker rgb 0.9 rgb <0.1, 0.5, 0.1> } }
sphere { <0, 6, 10>, 2 pigment { rgb <0.9, 0.7, 0.2> } }
