// golden-args: --block-mean 8
// A glass gem made of planes (an intersection of eight), bounded_by a box, as a photon
// target: POV-Ray shoots its photons at the sphere about the target's own box (here the
// bounded_by box), not about the surface's bounds.
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.01 } }
camera { location <0, 3.2, -4.5> look_at <0, 0.4, 0> angle 40 }
light_source { <2, 6, -3> rgb 1 photons { refraction on reflection on } }
plane { y, 0 pigment { rgb 0.8 } }
intersection {
  #declare K = 0;
  #while (K < 4)
    plane { <1, 0.8, 0>, 0.5 rotate y * (45 + 90 * K) }
    plane { <1, -1.2, 0>, 0.5 rotate y * (90 * K) }
    #declare K = K + 1;
  #end
  bounded_by { box { <-0.8, -0.6, -0.8>, <0.8, 0.9, 0.8> } }
  pigment { rgbf <0.6, 0.9, 1, 0.9> }
  finish { reflection 0.1 specular 0.6 }
  interior { ior 1.5 }
  photons { target reflection on refraction on }
  scale 0.8 rotate <15, 20, 0> translate <0, 0.7, 0>
}
