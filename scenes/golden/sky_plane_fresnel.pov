// A sky plane whose inside holds the camera (plane { y, 50 }): every camera ray starts
// inside it, and POV-Ray's fresnel then sees no reflection where a ray leaves the glass
// sphere (its relative ior compares the sphere with itself). rmse 0.026 to the same scene
// with the camera outside the plane.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 1.5, -5> look_at <0, 0.3, 0> angle 45 }
light_source { <-4, 6, -5> color rgb 1 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1,0.3,0.6> scale 0.5 } }
plane { y, 50 pigment { rgb <0.5, 0.6, 0.9> } finish { ambient 1 diffuse 0 } hollow }
sphere { <0, 0.3, 0>, 1 pigment { rgbf <1, 1, 1, 0.95> } finish { reflection { 0, 1 fresnel on } } interior { ior 1.5 } }
