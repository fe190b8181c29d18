// Coincident surfaces that POV-Ray decides by the order it tests objects in: two boxes
// whose top faces are coplanar and overlap, a box resting exactly on a plane with a face
// in it, and a union of coplanar boxes. POV-Ray keeps the first surface it tests at the
// smallest depth (trace/pov_order.h).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0, 0> angle 50 }
light_source { <-3, 8, -4> color rgb 1 }
// Written before the plane, its top face in it: POV-Ray tests infinite objects first.
box { <-1.5, -0.5, 2.5>, <1, 0, 4> pigment { rgb <1, 0.3, 0.1> } }
plane { y, 0 pigment { checker rgb 0.9 rgb <0.2, 0.3, 0.6> } }
box { <-3, 0, -1>, <-1, 1, 1> pigment { rgb <0.9, 0.2, 0.2> } }
box { <-2, 0, 0>, <0, 1, 2> pigment { rgb <0.2, 0.9, 0.2> } }
box { <0.5, -0.5, -1.5>, <2, 0, 0> pigment { rgb <0.9, 0.8, 0.1> } }
union {
  box { <-1, 0, -2.5>, <0.5, 0.5, -1.5> pigment { rgb <0.1, 0.8, 0.9> } }
  box { <-0.5, 0, -2.2>, <1, 0.5, -1.2> pigment { rgb <1, 0.5, 0.1> } }
}
// The same overlap written the other way round and boxes sharing a side face.
box { <1.5, 0, 0.5>, <3.5, 0.8, 2.5> pigment { rgb <0.3, 0.3, 0.9> } }
box { <0.8, 0, 1.2>, <2.6, 0.8, 3.2> pigment { rgb <0.9, 0.6, 0.6> } }
box { <-4, 0, 1.5>, <-2.5, 0.6, 3> pigment { rgb <0.6, 0.9, 0.6> } }
box { <-2.5, 0, 1.5>, <-1.5, 0.4, 3> pigment { rgb <0.6, 0.2, 0.4> } }
