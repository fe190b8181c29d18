// pavement as a media density: emitting and absorbing media shaped by hexagons seen
// through a hollow box, and by squares through a density_map of two densities.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -2.5> look_at <0, 0, 0> angle 58 }
light_source { <-5, 20, -10> color rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
box { <-2.6, -0.5, -1.4>, <-0.1, 0.3, 1.4> hollow
  pigment { rgbt 1 }
  interior { media { emission 0.8 absorption 0.5 method 3 samples 3
    density { pavement number_of_sides 6 number_of_tiles 3 pattern 2 interior 2 scale 0.3
      colour_map { [0 rgb 1] [0.6 rgb 0.2] [1 rgb 0] } } } } }
box { <0.1, -0.5, -1.4>, <2.6, 0.3, 1.4> hollow
  pigment { rgbt 1 }
  interior { media { emission <1, 0.6, 0.3> method 3 samples 3
    density { pavement number_of_sides 4 number_of_tiles 5 pattern 3 form 2 scale 0.3
      density_map { [0 rgb 1] [0.5 granite scale 0.4] [1 rgb 0] } } } } }
plane { y, -0.6 pigment { rgb 0.7 } }
