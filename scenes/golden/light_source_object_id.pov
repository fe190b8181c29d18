// light_source { Id ... } with a declared object that is no light is `object { Id ... }`
// (POV-Ray's Parse_Light_Source starts with Parse_Object_Id): a lamp, a union of a
// spotlight and its shade, placed so, at the top level, in a union and declared; and
// `adaptive` and `jitter` on lights without area_light, which POV-Ray keeps unused
// (FreeCAD's sun).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0, 0> angle 55 }
light_source { <3, 8, -4> color rgb 0.4 parallel point_at <0, 0, 0> adaptive 1 }
light_source { <-3, 8, -4> color rgb 0.2 jitter adaptive 2 }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.5 } }
#declare Lamp = union {
  light_source { <0, 1.5, 0> color rgb <1, 0.9, 0.7> spotlight point_at <0, 0, 0> radius 20 falloff 30 }
  cone { <0, 1.55, 0>, 0.1, <0, 1.2, 0>, 0.35 open pigment { rgb <0.8, 0.2, 0.1> } }
}
light_source { Lamp translate <-2, 0, 0> }
union { light_source { Lamp } sphere { <0, 0.3, 0>, 0.3 pigment { rgb 1 } } translate <2, 0, 0> }
#declare Lamp2 = light_source { Lamp rotate y * 20 translate <0, 0.3, 1.5> }
object { Lamp2 }
sphere { <-2, 0.4, 0>, 0.4 pigment { rgb <0.3, 0.8, 0.3> } }
