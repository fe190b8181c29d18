// One opaque box, a light behind its front face: the bumped normals that turn toward the
// light are shadowed by the box itself, as POV-Ray's shadow ray finds (no light-through).
#version 3.7;
camera { location <0,0,-8> look_at <0,0,0> angle 35 }
light_source{<500,50,20> rgb 1}
box { -1.5,1.5 texture { pigment {rgb 1} normal { bumps 1 } } }
