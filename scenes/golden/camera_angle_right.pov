// Square image with `right x*image_width/image_height`, a wide angle and direction length;
// a ring of spheres at the edges shows any error in the field of view.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <0, 0, -6>
  direction 2 * z
  right x * image_width / image_height
  up y
  angle 75
  look_at <0, 0, 0>
}
light_source { <0, 5, -8> color rgb <0.9, 1, 0.9> }
background { color rgb <0.1, 0.1, 0.15> }
#declare I = 0;
#while (I < 12)
  sphere { vrotate(<3.5, 0, 0>, z * I * 30), 0.5
    pigment { color rgb <I / 12, 1 - I / 12, 0.5> } finish { phong 0.3 } }
  #declare I = I + 1;
#end
