// A light's looks_like object in a scene too small for POV-Ray's bounding-slab tree (two
// objects, the light one of them): the light itself is tested, with no_shadow alone, so
// the object's own no_image and no_reflection do nothing.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -8> look_at <0, 0.2, 0> angle 52 }
background { rgb <0.3, 0.4, 0.5> }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.55 } finish { reflection 0.35 } }
light_source { <0, 0.4, 0> color rgb <1, 0.9, 0.7>
  looks_like { sphere { 0, 0.6 pigment { rgb <1, 0.9, 0.3> } finish { ambient 1 } no_image no_reflection } } }
