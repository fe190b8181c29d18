// Before 3.5 POV-Ray applied each camera item where it stood: here look_at turns the
// camera before location moves it (so the view keeps its old direction), angle then
// rescales the direction look_at left, right after look_at replaces the handed right
// vector, and rotate and translate move what is there at that point. A 3.5+ scene would
// apply them in its fixed order (right, direction, angle, up, sky, location, look_at).
#version 3.1;
camera {
  sky <0.2, 1, 0>
  look_at <1, -0.4, 4>
  location <0, 1.5, -6>
  angle 50
  right <1.5, 0, 0>
  rotate <0, 10, 0>
  translate <0.5, 0, 0>
}
light_source { <-5, 8, -6> color rgb 1 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb 0.3 } }
sphere { <0, 0.3, 0>, 1 pigment { color rgb <0.9, 0.5, 0.2> } finish { phong 0.6 } }
box { <1.5, -1, -0.5>, <2.5, 0.5, 0.5> pigment { color rgb <0.3, 0.6, 0.9> } }
cylinder { <-2, -1, 1>, <-2, 1.5, 1>, 0.5 pigment { color rgb <0.4, 0.8, 0.4> } }
