// light_group: a group's lights light only its objects; global_lights on lets the scene's
// lights light them too (off, the default, leaves them to the group's lights and the
// ambient); every object shadows every light, whichever group it is in. Groups move with
// their transforms (lights included), a declared group placed twice lights each copy by
// its own light, a group inside a group lights its objects by its own lights only while
// the outermost group decides about the global lights, and a group without lights
// leaves its objects unlit.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.6, 0> angle 55 }
light_source { <-7, 9, -5> color rgb 0.7 }
plane { y, 0 pigment { rgb 0.75 } }
// Red light from the right; its disc lies in the tall box's shadow (the box is in
// another group).
light_group {
  light_source { <5, 3.5, -3> color rgb <1, 0.35, 0.25> }
  sphere { <-2.5, 0.8, 0>, 0.8 pigment { rgb 1 } }
  disc { <-2, 0.01, 1>, y, 2.2 pigment { rgb 0.9 } }
}
// Blue light with the global lights, moved as a whole.
light_group {
  light_source { <-1, 4, -4> color rgb <0.3, 0.5, 1> }
  box { <-0.4, 0, -0.4>, <0.4, 2.2, 0.4> pigment { rgb 0.9 } }
  sphere { <1.2, 0.5, -0.6>, 0.5 pigment { rgb <1, 0.9, 0.6> } }
  global_lights on
  translate <0.6, 0, 0.3>
}
// Nested: the torus sees the green light and, through the outer group, the global
// light; the cone sees only the yellow light of its own group (the outer group's green
// light does not reach it) and the global light (the outer group's global_lights).
light_group {
  light_source { <4, 5, -2> color rgb <0.2, 1, 0.3> }
  torus { 0.6, 0.2 pigment { rgb 1 } translate <2.8, 0.2, 1.8> }
  light_group {
    light_source { <2, 4, -6> color rgb <1, 0.9, 0.2> }
    cone { <3.2, 0, -1.2>, 0.5, <3.2, 1.4, -1.2>, 0 pigment { rgb 1 } }
  }
  global_lights on
}
// No lights: only the ambient.
light_group { sphere { <-0.8, 0.35, -2.2>, 0.35 pigment { rgb 1 } } }
// Placed twice: each copy lit by its own magenta light only.
#declare Lamp = light_group {
  light_source { <0, 1.2, -1> color rgb <1, 0.3, 1> }
  sphere { 0, 0.3 pigment { rgb 1 } }
}
object { Lamp translate <-3.4, 0.3, -2> }
object { Lamp translate <-1.8, 0.3, -3> }
