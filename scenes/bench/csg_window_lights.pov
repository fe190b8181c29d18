// Benchmark scene: a difference with holes (a window: a slab of two planes less four
// boxes) lit through by 300 point lights, so every shadow ray crosses the CSG's children
// and tests their insides (reduced from a public scene of a ball on a floor).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { angle 20 location <3, 4, 20> look_at <0, 1, 0> right 4 * x / 3 }
plane { y, 0 pigment { rgb <1, 0.8, 0.3> } finish { phong 0.4 } }
sphere { y, 1 pigment { rgb 1 } finish { phong 0.4 } }
union {
  difference {
    intersection { plane { z, 0 } plane { -z, 0.1 } }
    union {
      box { -z, <1, 1, 1> }
      box { -z, <1, 1, 1> translate 1.1 * x }
      box { -z, <1, 1, 1> translate 1.1 * (x + y) }
      box { -z, <1, 1, 1> translate 1.1 * y }
    }
    pigment { rgb 0 }
  }
  #declare R1 = seed(35);
  #for (I, 1, 300)
    light_source { <0, 0, -3> + 2 * rand(R1) * x + 2 * rand(R1) * y color rgb 0.8 / 300 }
  #end
  scale 3 translate -10 * z + y - x
}
