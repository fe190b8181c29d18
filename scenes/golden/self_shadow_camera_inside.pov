// The camera inside a lone box, the light outside: the box shadows its own inside.
#version 3.7;
camera { location <0,0,0> look_at <0,0,1> angle 90 }
light_source{<50,30,-20> rgb 1}
box { -1.5,1.5 pigment {checker rgb 1 rgb 0.5} finish { ambient 0.1 } }
