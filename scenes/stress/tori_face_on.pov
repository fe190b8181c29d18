// Very thin tori seen face-on from close: rays cross the tube at right angles, roots 2e-4 apart.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, 0> look_at <0, 0, 0> angle 50 }
light_source { <3, 10, -4> rgb 1 }
torus { 1, 1e-2 pigment { rgb <0.9, 0.9, 0.2> } }
torus { 0.8, 1e-3 pigment { rgb <0.2, 0.9, 0.2> } }
torus { 0.6, 0.999 * 0.6 pigment { rgb <0.9, 0.2, 0.2> } scale 0.5 }
torus { 1.2, 1e-4 pigment { rgb 1 } }
