// light_source { projected_through { OBJECT } } (POV-Ray 3.7's TracePointLightShadowRay):
// the light reaches a point only when the line to the light crosses the object before the
// light; then only what lies before that crossing shadows it. The object itself is never
// seen and casts no shadow; its visible copy here sits where the mask is. Each light kind,
// a CSG mask moved with its light, a shadowless light, a declared light copied and moved,
// a glass blocker before the mask and an opaque one between mask and light (which does
// not shadow), reflections and refraction of the lit wall.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -9> look_at <0, 1.5, 0> angle 60 }
background { rgb <0.1, 0.12, 0.15> }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.6 } finish { reflection 0.15 } }
plane { z, 2 pigment { rgb <0.9, 0.85, 0.8> } }
#declare Window = difference {
  box { <-1, -1, -0.05>, <1, 1, 0.05> }
  cylinder { <-0.4, 0.3, -1>, <-0.4, 0.3, 1>, 0.3 }
  box { <0.05, -0.8, -1>, <0.8, 0.0, 1> }
}
// A point light through a CSG mask; the visible copy of the mask is offset so that it
// shows beside it.
light_source { <-2, 3, -6> color rgb <1, 0.9, 0.7>
  projected_through { object { Window scale 0.8 translate <0, 0, -3> } }
  translate <-0.5, 0, 0> }
object { Window scale 0.8 translate <-1.2, 0.8, -4.2> pigment { rgb <0.3, 0.6, 0.3> } }
// A spotlight through a sphere, with an opaque box between the sphere and the light
// (no shadow) and a glass ball before the sphere (a coloured shadow).
light_source { <3, 4, -7> color rgb <0.5, 0.7, 1> spotlight point_at <1.5, 1, 2>
  radius 20 falloff 30 projected_through { sphere { <2.4, 2.9, -4.3>, 0.5 } } }
box { <2.5, 3.2, -5.6>, <3.2, 3.9, -5.2> pigment { rgb <0.8, 0.2, 0.2> } }
sphere { <1.9, 1.8, -1>, 0.45 pigment { rgbf <1, 0.6, 0.6, 0.8> }
  interior { ior 1.3 } finish { specular 0.4 } }
// A shadowless light through a box: masked, no shadows.
light_source { <0, 6, -3> color rgb 0.35 shadowless
  projected_through { box { <-0.6, 3.4, -2.4>, <0.6, 3.6, -1.2> } } }
// A parallel light through a torus.
light_source { <-6, 5, -2> color rgb <0.6, 0.5, 0.3> parallel point_at <0, 0, 0>
  projected_through { torus { 0.6, 0.15 rotate z * 50 translate <-3.5, 2.9, -1.2> } } }
// A declared light with its mask, placed twice by its copies' translations.
#declare Lamp = light_source { <0, 1.2, -5> color rgb <0.4, 0.3, 0.5>
  projected_through { cylinder { <0, 1, -4>, <0, 1, -3.9>, 0.35 } } }
light_source { Lamp translate <2.5, 0, 0> }
light_source { Lamp translate <-2.5, 0, 1> }
// An unmasked fill light, and a blocker that shadows the masked light's patch.
light_source { <0, 3, -9> color rgb 0.25 }
cylinder { <-1.9, 0, 0.5>, <-1.9, 1.0, 0.5>, 0.15 pigment { rgb <0.9, 0.8, 0.2> } }
