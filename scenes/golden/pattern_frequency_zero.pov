// quilted starts at frequency 0 as in POV-Ray: phase alone does nothing, an explicit
// frequency wraps; a block pattern's phase alone does nothing either.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -4> look_at 0 angle 50 }
light_source { <-3, 5, -6> rgb 1 }
plane { z, 0 pigment { quilted control0 0.3 control1 0.8 frequency 2 phase 0.3 color_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] } scale 0.5 } finish { ambient 0.3 } }
sphere { <-1, 0.5, -1>, 0.6 pigment { quilted phase 0.4 color_map { [0 rgb 1] [1 rgb <0,1,0>] } scale 0.2 } }
sphere { <1, 0.5, -1>, 0.6 pigment { quilted frequency 3 phase 0.4 color_map { [0 rgb 1] [1 rgb <0,1,0>] } scale 0.2 } }
sphere { <0, -0.8, -1>, 0.6 pigment { checker rgb 1 rgb 0 phase 0.5 scale 0.3 } }
