// frequency, phase and waves on block patterns (checker, hexagon, brick, square,
// triangular, cubic) and the object pattern: POV-Ray wraps the entry number as any
// pattern's value (fmod(v * frequency + phase, 1.00001), negative values folded) and
// shapes it by the wave, then blends the two neighbouring entries of the list. Pigment,
// texture and normal lists.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 9, -9> look_at <0, 0, 0.5> angle 62 }
light_source { <-4, 12, -6> rgb 1 }
light_source { <5, 6, -8> rgb 0.4 }
#declare F = finish { ambient 0.15 diffuse 0.8 }
// Row 1: pigment lists.
box { <-6, 0, 3>, <-3.2, 0.2, 6> pigment { checker rgb <1, 0, 0>, rgb <0, 0, 1> frequency 0.3 scale 0.5 } finish { F } }
box { <-3, 0, 3>, <-0.2, 0.2, 6> pigment { hexagon rgb <1, 0, 0>, rgb <0, 1, 0>, rgb <0, 0, 1> frequency -0.7 phase 0.2 scale 0.5 } finish { F } }
box { <0, 0, 3>, <2.8, 0.2, 6> pigment { brick rgb <0.9, 0.9, 0.8>, rgb <0.6, 0.2, 0.1> sine_wave scale 0.15 } finish { F } }
box { <3, 0, 3>, <5.8, 0.2, 6> pigment { square rgb <1, 0, 0>, rgb <0, 1, 0>, rgb <0, 0, 1>, rgb <1, 1, 0> triangle_wave frequency 0.45 scale 0.4 } finish { F } }
// Row 2: more lists, turbulence, cubic waves.
box { <-6, 0, -0.5>, <-3.2, 0.2, 2.5> pigment { triangular rgb 0, rgb <1, 0, 0>, rgb <0, 1, 0>, rgb <0, 0, 1>, rgb <1, 1, 0>, rgb 1 frequency 0.15 cubic_wave scale 0.5 } finish { F } }
box { <-3, 0, -0.5>, <-0.2, 0.2, 2.5> pigment { checker rgb <1, 0.5, 0>, rgb <0, 0.3, 1> turbulence 0.5 frequency 0.1 scale 0.4 } finish { F } }
box { <0, 0, -0.5>, <2.8, 0.2, 2.5> pigment { cubic rgb <1, 0, 0>, rgb <0, 1, 0>, rgb <0, 0, 1>, rgb <1, 1, 0>, rgb <0, 1, 1>, rgb <1, 0, 1> frequency 0.35 scale 0.5 } finish { F } }
box { <3, 0, -0.5>, <5.8, 0.2, 2.5> pigment { object { sphere { <4.4, 0.2, 1>, 1 } rgb <0.2, 0.2, 0.8>, rgb <1, 0.8, 0.1> } scallop_wave } finish { F } }
// Row 3: texture and normal lists.
box { <-6, 0, -4>, <-3.2, 0.2, -1> texture { checker texture { pigment { rgb <1, 0, 0> } finish { F } }
      texture { pigment { rgb <0, 0, 1> } finish { F phong 0.8 } } frequency 0.4 phase 0.1 scale 0.5 } }
box { <-3, 0, -4>, <-0.2, 0.2, -1> texture { hexagon texture { pigment { rgb <1, 1, 0> } finish { F } }
      texture { pigment { rgb <0, 1, 1> } finish { F } } texture { pigment { rgb <1, 0, 1> } finish { F } } sine_wave scale 0.5 } }
box { <0, 0, -4>, <2.8, 0.2, -1> pigment { rgb 0.8 } finish { F phong 0.6 }
      normal { checker normal { bumps 1 scale 0.1 }, normal { dents 0.8 scale 0.2 } frequency 0.5 scale 0.6 } }
box { <3, 0, -4>, <5.8, 0.2, -1> pigment { rgb 0.8 } finish { F phong 0.6 }
      normal { hexagon normal { agate 1 }, normal { granite 0.6 }, normal { wrinkles 1 } frequency -0.4 poly_wave 2 scale 0.5 } }
plane { y, -0.01 pigment { rgb 0.3 } }
