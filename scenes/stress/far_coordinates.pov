// Objects 1e6 to 1e7 from the origin with sizes down to 1e-3, camera beside them: every
// coordinate carries ~7 digits of offset before the shape's own digits start.
#version 3.7;
global_settings { assumed_gamma 1 }
#declare C = <3e6, 1e6, 7e6>;
camera { location C + <0, 0.002, -0.01> look_at C angle 40 }
light_source { C + <1, 2, -3> rgb 1 }
background { rgb <0.1, 0.1, 0.2> }
sphere { C + <-0.002, 0, 0>, 1e-3 pigment { rgb <1, 0.3, 0.3> } }
box { C + <0.0005, -0.0005, -0.0005>, C + <0.0015, 0.0005, 0.0005> pigment { rgb <0.3, 1, 0.3> } }
torus { 1e-3, 3e-4 pigment { rgb <0.3, 0.3, 1> } translate C + <0, 0.0015, 0.001> }
cylinder { C + <-0.003, -0.0012, 0>, C + <0.003, -0.0012, 0>, 2e-4 pigment { rgb 1 } }
triangle { C + <-0.004, -0.002, 0.002>, C + <0.004, -0.002, 0.002>, C + <0, 0.003, 0.002>
  pigment { rgb <0.8, 0.8, 0.5> } }
