// Transforms and warps in the order written: POV-Ray keeps them in one list, so a
// transform written before a warp acts after it on the way into pattern space, and one
// written after it before it. Four panels of the same brick pattern: turbulence warp
// after / before a rotate, a repeat warp between a scale and a translate, and a normal
// with a turbulence warp between two transforms. The classic `turbulence` keyword stays
// last wherever it is written.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at 0 angle 50 }
light_source { <-5, 10, -20> color rgb 1 }
background { rgb <0.1, 0.1, 0.2> }
#declare Bricks = pigment { brick rgb <0.9, 0.9, 0.8> rgb <0.7, 0.2, 0.1>
                            brick_size <1, 0.4, 1> mortar 0.08 translate 0.01 scale 0.6 }
#declare Panel = box { <-1.9, -1.9, 0>, <1.9, 1.9, 0.1> }
object { Panel pigment { Bricks rotate 60 * z warp { turbulence 0.4 * x octaves 2 } }
         translate <-2.1, 2.1, 0> }
object { Panel pigment { Bricks warp { turbulence 0.4 * x octaves 2 } rotate 60 * z }
         translate <2.1, 2.1, 0> }
object { Panel pigment { Bricks scale <2, 1, 1> warp { repeat 0.7 * x flip y }
                         translate <0.3, 0.2, 0> turbulence 0.2 }
         translate <-2.1, -2.1, 0> }
object { Panel pigment { rgb <0.8, 0.8, 0.9> }
         normal { bumps 0.8 scale 0.3 rotate 45 * z warp { turbulence 0.6 * y }
                  scale <2, 1, 1> }
         finish { specular 0.5 }
         translate <2.1, -2.1, 0> }
