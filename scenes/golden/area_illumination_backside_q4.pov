// golden-args: +Q4
// area_illumination_backside.pov at +Q4: no area grids, so each light is its centre, and
// POV-Ray then skips the test that leaves a surface facing away from it unlit.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0, 0> }
light_source { <0, -1, 0> color rgb 1 area_light 4*x, 4*z, 4, 4 area_illumination on }
light_source { <0, 1.5, 1> color rgb 1 area_light 6*x, 0.5*z, 5, 2 area_illumination on }
light_source { <0, 5, -5> color rgb 0.2 }
plane { y, 0 pigment { rgb 0.8 } finish { diffuse 0.6, 0.3 phong 0.5 } }
sphere { <-1,0.5,0>, 0.5 pigment { rgb 0.8 } finish { specular 0.5 } }
sphere { <1,0.5,0>, 0.5 pigment { rgb 0.8 } finish { phong 0.5 irid { 0.3 thickness 0.5 turbulence 0.2 } } double_illuminate }
