// A light's looks_like object: POV-Ray tests the light's flags (no_shadow alone), never
// the object's own (a no_image or no_reflection looks_like stays visible there), but a CSG
// looks_like tests its children's flags by its own rules.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -8> look_at <0, 0.2, 0> angle 52 }
light_source { <-7, 7, -5> color rgb 1 }
background { rgb <0.3, 0.4, 0.5> }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.55 } finish { reflection 0.35 } }
// A see-through pane with no ior in front of the lower half: what the camera sees through
// it comes by refracted rays (image rays, not primary rays).
box { <-5, -1, -2.6>, <5, 1.0, -2.5> pigment { rgbf <1, 1, 1, 0.85> } }
#declare Red = texture { pigment { rgb <0.9, 0.15, 0.1> } }
#declare Blue = texture { pigment { rgb <0.15, 0.35, 0.9> } }
light_source { <-1.5, 0.2, 0> color rgb <1, 0.9, 0.7>
  looks_like { sphere { 0, 0.5 pigment { rgb <1, 0.9, 0.3> } finish { ambient 1 } no_image } } }
light_source { <1.5, 0.2, 0> color rgb <0.7, 0.8, 1>
  looks_like { merge { sphere { 0, 0.5 pigment { rgb <0.3, 0.9, 1> } finish { ambient 1 } no_image }
                       box { <-0.2, -0.7, -0.2>, <0.6, 0.3, 0.6> pigment { rgb <0.3, 1, 0.3> } no_reflection } } } }
sphere { <0, -0.4, 1.5>, 0.6 texture { Red } }
