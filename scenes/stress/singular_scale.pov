// A singular transform: scale by 0 must be a located error, not a flattened object.
#version 3.7;
camera { location <0, 0, -5> look_at 0 }
sphere { 0, 1 scale <1, 0, 1> pigment { rgb 1 } }
