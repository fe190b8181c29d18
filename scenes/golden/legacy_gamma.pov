// No #version and no assumed_gamma: POV-Ray 3.7 writes colours raw (no gamma handling).
camera { location <0, 0, -4> look_at 0 }
light_source { <2, 4, -3> color rgb 1 }
background { color rgb <0.5, 0.5, 0.5> }
sphere { 0, 1 pigment { color rgb <0.5, 0.7, 0.2> } finish { phong 0.4 } }
box { <-2, -1.5, 0>, <2, -1.2, 2> pigment { color rgb 0.25 } finish { ambient 1 diffuse 0 } }
