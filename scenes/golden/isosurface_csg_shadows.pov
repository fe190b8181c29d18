// A see-through isosurface inside CSG and its shadows: POV-Ray restarts a shadow ray at
// each see-through surface it meets, and the CSG hands the restarted ray to the
// isosurface, whose one batch of roots (max_trace) then starts there; so every sheet
// dims the light, on the surface itself and on the floor. In an intersection, a
// difference and an unsplit union; a light among the sheets too.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <9, 8, -12> look_at <0, -1, 0> angle 45 }
light_source { <30, 30, 30> color rgb 1 }
light_source { <-2, 0.5, -1> color rgb 0.4 }
plane { y, -4 pigment { checker rgb 0.9 rgb 0.5 scale 2 } }
#declare Sheets = isosurface {
  function { sin(x * z * 0.6) + y }
  max_gradient 10
  contained_by { box { <-4, -3, -4>, <4, 3, 4> } }
  pigment { rgbf <0.2, 1, 1, 0.5> }
}
intersection { object { Sheets } sphere { 0, 3.8 pigment { rgbf <1, 0.6, 0.6, 0.6> } } }
difference {
  object { Sheets pigment { rgbf <1, 1, 0.3, 0.5> } }
  box { <-5, -5, -5>, <0, 5, 0> }
  translate <-1, 0, 7>
}
union { object { Sheets pigment { rgbt <0.3, 0.4, 1, 0.5> } } sphere { <0, 3, 0>, 0.5 }
        split_union off translate <7, 0, 1> }
