// The virtual-walls test scene: 5000 random reflective spheres floating over a mirror-ish
// floor, placed with POV-Ray's own seed()/rand() stream, traced to depth 5.
// Render square: povwall render scenes/demo/walls.pov -W 600 -H 600
#version 3.7;
#include "colors.inc"

global_settings {
    assumed_gamma 1.0
    max_trace_level 5
}

#declare Count = 5000;
#declare Half = 14;     // spheres fill x and z in [-Half, Half] ...
#declare Top = 9;       // ... and y in [0.2, Top]

camera {
    location <0, 13, -25>
    look_at <0, 2.5, 2>
    right x * image_width / image_height
    angle 58
}

light_source { <-30, 45, -40> color White }
light_source { <25, 15, -30> color rgb <0.35, 0.33, 0.3> }

background { color rgb <0.006, 0.008, 0.02> }

plane {
    y, 0
    pigment { color rgb <0.32, 0.34, 0.38> }
    finish { ambient 0.05 diffuse 0.6 reflection 0.25 }
}

#declare R = seed(1997);
#declare I = 0;
#while (I < Count)
    #declare P = <(2 * rand(R) - 1) * Half, 0.2 + rand(R) * (Top - 0.2), (2 * rand(R) - 1) * Half>;
    sphere {
        P, 0.12 + 0.3 * rand(R)
        pigment { color rgb <0.25 + 0.75 * rand(R), 0.25 + 0.75 * rand(R), 0.25 + 0.75 * rand(R)> }
        finish { ambient 0.06 diffuse 0.65 phong 0.7 phong_size 80 reflection 0.4 }
    }
    #declare I = I + 1;
#end
