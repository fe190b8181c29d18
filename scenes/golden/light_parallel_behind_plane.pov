// A parallel light's depth is the distance to its plane, negative behind it: nothing
// shadows a point there (POV-Ray's shadow test over a negative depth finds nothing), so
// the spheres behind the light at the origin are lit on their light side though one
// stands in front of the other, while those in front of the plane shadow each other.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <10, 1, 0> look_at <0, 0, 0> angle 70 }
light_source { <0, 0, 0> rgb 1 parallel point_at <0, 0, 1> }
sphere { <0, 0, -2>, 1 pigment { rgb 1 } }
sphere { <0, 0, -4.5>, 1 pigment { rgb <1, 0.6, 0.4> } }
sphere { <0, 0, 2.5>, 1 pigment { rgb <0.4, 0.6, 1> } }
sphere { <0, 0.3, 5>, 1 pigment { rgb 1 } }
