// golden-args: --block-mean 8
// Subsurface light transport on a sphere: colour translucency, ior 1.3, mm_per_unit 5 (the
// diffuse, single-scattering and see-through terms all show), a back light that shows through.
// POV-Ray draws its samples from per-thread streams: compared as 8x8 block means.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  mm_per_unit 5
  subsurface { samples 40, 10 }
}
camera { location <0, 1.2, -3.5> look_at <0, 0.6, 0> angle 40 }
light_source { <-3, 5, -4> color rgb 1 }
light_source { <2, 1.5, 4> color rgb <0.6, 0.6, 0.7> }   // back light: shows light bleeding through
plane { y, 0 pigment { color rgb 0.7 } finish { diffuse 0.7 ambient 0.1 } }
sphere { <0, 0.7, 0>, 0.7
  pigment { color rgb <0.9, 0.6, 0.4> }
  finish { diffuse 0.8 specular 0.3 roughness 0.02 ambient 0
           subsurface { translucency <3, 1.5, 0.8> } }
  interior { ior 1.3 }
}
