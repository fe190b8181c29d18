// Thin large tori without `sturm`: POV-Ray solves their quartic in closed form, which loses
// roots (holes where the tube should be) and accuracy; its pixels come from those roots,
// and so do ours. With `sturm`, the same rings are whole. A glass ring and a ring cut by a
// difference show the lost roots inside CSG and refraction too.
#version 3.7;
global_settings { assumed_gamma 1 ambient_light rgb 1 }
camera { orthographic location <0, 0, -150> look_at <0, 0, 0> right x * 200 up y * 150 }
light_source { <500, 800, -1000> rgb 0.6 }
background { rgb <0.1, 0.2, 0.3> }
// Edge-on: the rings of a spacecraft scene.
torus { 70, 1.25 rotate 90 * z pigment { rgb 0.8 } finish { ambient 0.3 } translate <-60, 0, 0> }
torus { 70, 1.25 sturm rotate 90 * z pigment { rgb <1, 0.7, 0.4> } finish { ambient 0.3 }
        translate <-40, 0, 0> }
// Seen at a slant, in glass, over a checker floor.
torus { 40, 0.8 rotate <70, 0, 10> translate <40, 20, 0>
        pigment { rgbf <0.9, 1, 0.9, 0.9> } finish { reflection 0.1 }
        interior { ior 1.5 } }
// Cut in half by a difference, and a clipped one.
difference {
  torus { 45, 0.9 rotate <80, 20, 0> }
  box { <-100, -100, -100>, <0, 100, 100> }
  pigment { rgb <0.4, 1, 0.4> } translate <30, -40, 0>
}
torus { 30, 0.6 rotate <85, -30, 0> clipped_by { plane { y, 5 } }
        pigment { rgb <1, 0.4, 0.4> } translate <60, -20, 10> }
plane { z, 5 pigment { checker rgb 0.3 rgb 0.6 scale 10 } }
