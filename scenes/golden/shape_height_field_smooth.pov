// height_field smooth (POV-Ray's vertex normals, blended bilinearly after the transform)
// beside the faceted one, water_level, hierarchy off (its own block walk), and a field
// scaled unevenly and turned.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -6> look_at <0, 0.2, 0> angle 50 }
light_source { <-5, 10, -7> color rgb 1 }
light_source { <6, 5, -2> color rgb 0.35 }
#declare T = texture { pigment { rgb <0.85, 0.75, 0.55> } finish { specular 0.5 roughness 0.02 } }
height_field { png "images/hf_grey16.png" smooth texture { T }
               translate <-0.5, 0, -0.5> scale <2.4, 1.2, 2.4> translate <-1.4, 0, 1> }
height_field { png "images/hf_grey16.png" texture { T }
               translate <-0.5, 0, -0.5> scale <2.4, 1.2, 2.4> translate <1.4, 0, 1> }
height_field { png "images/hf_grey8.png" smooth water_level 0.3 hierarchy off texture { T }
               translate <-0.5, 0, -0.5> scale <2, 0.8, 1.6> rotate <10, 25, 0> translate <-1.4, 0, -1.5> }
height_field { png "images/hf_palette.png" water_level 0.25 smooth texture { T }
               translate <-0.5, 0, -0.5> scale <2, 1, 2> rotate <0, -30, 8> translate <1.4, 0, -1.5> }
