// hollow on a union reaches its children (POV-Ray's parser passes it down), so fog fills
// the transparent union; a solid transparent sphere beside it keeps the fog out.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.3, 0> angle 45 }
light_source { <-4, 6, -5> color rgb 1 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb <0.1, 0.3, 0.6> scale 0.5 } }
fog { distance 6 color rgb <0.8, 0.8, 0.9> }
union { sphere { <-0.5, 0, 0>, 0.6 } sphere { <0.3, 0, 0>, 0.6 } pigment { rgbt <1, 1, 1, 0.9> } hollow translate <-0.8, 0, 0> }
sphere { <1.4, 0, 0>, 0.6 pigment { rgbt <1, 1, 1, 0.9> } }
sphere { <0, 0, 4>, 0.8 pigment { rgb 1 } }
