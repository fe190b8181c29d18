// A 64 x 64 field of random spikes: the block walk (8 x 8 blocks) with the hierarchy on
// and the single-block DDA with it off, at a low angle where the first cell that hits
// decides (POV-Ray reports that cell's hit, not a nearer one farther on).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.9, -3.2> look_at <0, 0.1, 0.3> angle 55 }
light_source { <-5, 10, -7> color rgb 1 }
light_source { <6, 3, -4> color rgb 0.4 }
height_field { png "images/hf_spikes.png" pigment { rgb <0.9, 0.6, 0.4> }
               translate <-0.5, 0, -0.5> scale <1.9, 0.5, 1.9> rotate 20*y translate <-1, 0, 0.4> }
height_field { png "images/hf_spikes.png" hierarchy off pigment { rgb <0.5, 0.7, 0.9> }
               translate <-0.5, 0, -0.5> scale <1.9, 0.5, 1.9> rotate -15*y translate <1, 0, 0.4> }
