// sor and lathe seen edge-on: the camera's horizontal plane crosses every object, so a
// few image rows meet them nearly perpendicular to their axes. There POV-Ray's
// closed-form cubic (sor) and quartic (quadratic_spline lathe) have a tiny leading
// coefficient and their roots are round-off: which of those pixels hit depends on the
// camera ray's last bits (its direction length from the angle times POV-Ray's M_PI_360:
// angle 59 rounds differently as 59 * pi / 360). The shadow rays leaving those surfaces
// meet them again through round-off roots between 1e-4 and 1e-3, which shadow the point
// when the surface is the light's cached blocker (POV-Ray tests it first, from 1e-4).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.3, 0.62, -7> look_at <0, 0.55, 0> angle 59 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 3, -5> color rgb 0.35 }
background { rgb <0.2, 0.3, 0.6> }
#declare F = finish { specular 0.4 roughness 0.03 }
// Closed, open, and scaled (the rows cross them at different heights of their profiles).
sor { 6, <0.794, -1.2>, <0.431, -1>, <0.401, -0.4>, <0.474, 0.3>, <0.815, 1>, <0.218, 1.2>
      pigment { rgb <0.9, 0.5, 0.3> } finish { F } translate <-2.6, 0.2, 0> }
sor { 6, <0.394, -1.2>, <0.897, -1>, <0.75, -0.4>, <0.286, 0.3>, <0.62, 1>, <0.773, 1.2> open
      pigment { rgb <0.4, 0.8, 0.4> } finish { F } translate <-0.9, 0.1, 0.3> }
sor { 6, <0.267, -1.2>, <0.415, -1>, <0.263, -0.4>, <0.892, 0.3>, <0.763, 1>, <0.232, 1.2>
      pigment { rgb <0.9, 0.9, 0.4> } finish { F } scale <1.1, 1.3, 0.9> translate <0.9, 0, 0.5> }
lathe { quadratic_spline 6, <0.922, -1>, <0.205, -0.6>, <0.781, -0.2>, <0.686, 0.2>,
        <0.592, 0.6>, <0.804, 1> pigment { rgb <0.5, 0.6, 1> } finish { F } translate <2.7, 0.4, 0.2> }
