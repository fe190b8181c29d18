// A map given after a pigment identifier replaces the identifier's map, of either kind
// (POV-Ray's Parse_Pigment destroys the old blend map): a pigment_map replacing a
// pigment_map (advanced/wallstucco.pov's brick wall), a colour_map replacing a
// pigment_map, a pigment_map replacing a colour_map, and a second map in one block.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at 0 angle 50 }
light_source { <-5, 8, -10> rgb 1 }
#declare Mapped = pigment {
  gradient x
  pigment_map {
    [0, granite scale 0.2 colour_map { [0 rgb 0] [1 rgb <0.3, 0.3, 0.6>] }]
    [0.5, checker rgb <1, 0.8, 0.2> rgb <0.2, 0.6, 0.2> scale 0.15]
  }
  scale 2
}
#declare Coloured = pigment { onion colour_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } scale 0.7 }
box { <-4, 0.2, 0>, <-0.2, 3, 0.5>
  pigment { Mapped pigment_map { [0, rgb 0.6] [0.5, rgb <0.6, 0.3, 0.25>] } } }
box { <0.2, 0.2, 0>, <4, 3, 0.5>
  pigment { Mapped colour_map { [0 rgb <0.9, 0.9, 0.2>] [1 rgb <0.1, 0.4, 0.9>] } } }
box { <-4, -3, 0>, <-0.2, -0.2, 0.5>
  pigment { Coloured pigment_map { [0, rgb 1] [0.5, bozo scale 0.3] [1, rgb <0.9, 0.3, 0.6>] } } }
box { <0.2, -3, 0>, <4, -0.2, 0.5>
  pigment { Coloured pigment_map { [0, rgb 0] [1, rgb 1] } pigment_map { [0, rgb <0.3, 0.9, 0.3>] [1, rgb <0.9, 0.2, 0.2>] } } }
