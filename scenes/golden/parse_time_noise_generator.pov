// A pattern function called while parsing uses the noise_generator set so far (here 1,
// POV-Ray's original noise), as the render does: the spheres' sizes come from it.
#version 3.6;
global_settings { assumed_gamma 1.0 noise_generator 1 }
#declare F = function { pattern { pigment_pattern { agate color_map { [0.4 rgb 0] [0.6 rgb 1] } scale 0.8 } } }
#declare G = function { pattern { agate scale 0.8 } }
camera { location <0, 0, -5> look_at 0 angle 40 }
light_source { <-3, 4, -5> color rgb 1 }
#declare I = 0;
#while (I < 5)
  sphere { <I - 2, 0.6, 0>, 0.1 + 0.35 * G(I * 0.13, 0.2, 0) pigment { rgb <1, 0.6, 0.2> } }
  sphere { <I - 2, -0.6, 0>, 0.1 + 0.35 * F(I * 0.21, 0.25, 0) pigment { rgb <0.2, 0.6, 1> } }
  #declare I = I + 1;
#end
