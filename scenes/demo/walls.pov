// The virtual-walls test scene: 5000 random reflective spheres in a cube, placed with
// POV-Ray's own rand() stream, traced to depth 5. Render square (600x600).
#version 3.7;
#include "colors.inc"

global_settings {
    assumed_gamma 1.0
    max_trace_level 5
}

#declare Count = 5000;
#declare Spread = 10;

camera {
    location <0, 0, -22>
    look_at <0, 0, 0>
    right x
    angle 48
}

light_source { <-30, 40, -50> color White }
light_source { <35, 10, -30> color rgb <0.45, 0.42, 0.38> }

background { color rgb <0.05, 0.07, 0.12> }

#declare R = seed(1997);
#declare I = 0;
#while (I < Count)
    #declare P = <rand(R), rand(R), rand(R)> * 2 * Spread - Spread;
    sphere {
        P, 0.25 + 0.35 * rand(R)
        pigment { color rgb <0.3 + 0.7 * rand(R), 0.3 + 0.7 * rand(R), 0.3 + 0.7 * rand(R)> }
        finish { ambient 0.08 diffuse 0.7 phong 0.6 phong_size 60 reflection 0.35 }
    }
    #declare I = I + 1;
#end
