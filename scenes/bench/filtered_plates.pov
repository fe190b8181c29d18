// Benchmark scene: rays through stacks of see-through plates (rgbf, no ior), as mirror
// and glass-shelf figures have them: 40 thin boxes on the left, 40 intersections of two
// thin prisms on the right, 0.05 apart, so that one octree leaf holds several plates and
// each ray is passed on from plate to plate (reduced from the point-group figures of a
// public repository, where every mirror is such an intersection).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 60 }
camera { location <0, 0, -3.2> look_at 0 right 2 * x up y }
light_source { <-5, 5, -5> rgb 1 shadowless }
background { rgb <0.3, 0.3, 0.3> }
#declare Plate = box { <-0.7, -0.005, -0.7>, <0.7, 0.005, 0.7>
  texture { pigment { rgbf <1, 1, 1, 0.97> } finish { ambient 0.1 diffuse 0.1 } } rotate 90 * x }
#declare Mirror = intersection {
  prism { -0.005, 0.005, 5 <1, 0>, <0, 1>, <-1, 0>, <0, -1>, <1, 0>
    texture { pigment { rgbf <1, 0.95, 0.9, 0.97> } finish { ambient 0.1 diffuse 0.1 } } }
  prism { -0.006, 0.006, 5 <0.999, 0>, <0, 0.999>, <-0.999, 0>, <0, -0.999>, <0.999, 0>
    texture { pigment { rgb 0 } } }
  rotate 90 * x }
#declare I = 0;
#while (I < 40)
  object { Plate translate <-1.1, 0, I * 0.05> }
  object { Mirror translate <1.1, 0, I * 0.05> }
  #declare I = I + 1;
#end
