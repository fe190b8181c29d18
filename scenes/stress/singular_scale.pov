// A scale by 0: POV-Ray warns and scales by 1 in that axis instead (Parse_Scale_Vector),
// so the sphere renders unflattened.
#version 3.7;
camera { location <0, 0, -5> look_at 0 }
light_source { <3, 5, -5> color rgb 1 }
sphere { 0, 1 scale <1, 0, 1> pigment { rgb 1 } }
