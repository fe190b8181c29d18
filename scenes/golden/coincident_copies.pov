// Many coincident copies (exporters write one part per colour and LDraw models repeat a
// brick in place): every ray meets dozens of surfaces at one depth and POV-Ray keeps the
// one its bounding tree tests first. Copies of a sphere, of a mesh and of a box, each in
// its own colour, and copies half-overlapping, so the colour seen is POV-Ray's order.
// (Each ray's ties are ranked with one walk of that tree: trace/prepared_scene.cpp.)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-3, 8, -4> color rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
#declare Brick = mesh {
  triangle { <-0.4, 0, -0.4>, <-0.4, 0.9, -0.4>, <0.4, 0.9, -0.4> }
  triangle { <-0.4, 0, -0.4>, <0.4, 0.9, -0.4>, <0.4, 0, -0.4> }
  triangle { <-0.4, 0.9, -0.4>, <-0.4, 0.9, 0.4>, <0.4, 0.9, 0.4> }
  triangle { <-0.4, 0.9, -0.4>, <0.4, 0.9, 0.4>, <0.4, 0.9, -0.4> }
  triangle { <-0.4, 0, -0.4>, <-0.4, 0.9, -0.4>, <-0.4, 0.9, 0.4> }
  triangle { <-0.4, 0, -0.4>, <-0.4, 0.9, 0.4>, <-0.4, 0, 0.4> }
}
#declare I = 0;
#while (I < 160)
  #declare C = <mod(I, 7) / 6, mod(I, 5) / 4, mod(I, 3) / 2>;
  sphere { <-2, 0.8, 0>, 0.8 pigment { rgb C } }
  object { Brick pigment { rgb 1 - C } translate <0, 0, 0.5> }
  box { <1.2, 0, -0.5>, <2.8, 1, 0.5> pigment { rgb <C.z, C.x, C.y> } }
  box { <1.2 + mod(I, 2) * 0.4, 0, 0.7>, <2.4 + mod(I, 2) * 0.4, 0.6, 1.5>
        pigment { rgb <C.y, C.z, C.x> } }
  #declare I = I + 1;
#end
