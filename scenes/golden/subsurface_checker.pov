// golden-args: --block-mean 8
// Subsurface as in the corpus scene: a checker of two subsurface textures on an infinite plane
// with fresnel reflection and conserve_energy, ambient_light, a sky_sphere, and a subsurface blob.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  mm_per_unit 40
  subsurface { samples 40, 8 }
  ambient_light 0.3
}
camera { location <0.0, 2.5, -4.0> angle 50 right x*image_width/image_height look_at <0.5, 1.0, 0.0> }
sky_sphere { pigment { gradient y color_map { [0.0 rgb <0.6,0.7,1.0>] [0.7 rgb <0.0,0.1,0.8>] } } }
light_source { <-30, 30, -30> color rgb <1,1,1> }
plane { y, -0.01
  texture { checker
    texture { pigment { color rgb <0.83,0.79,0.75> }
              finish { diffuse 0.8 specular 0.6 reflection { 0.2 fresnel } conserve_energy
                       subsurface { translucency <0.4562, 0.3811, 0.3325> } } }
    texture { pigment { color rgb 0.03 }
              finish { diffuse 0.8 specular 0.6 reflection { 0.2 fresnel } conserve_energy
                       subsurface { translucency <0.4562, 0.3811, 0.3325> } } }
    scale 4 translate <0.7,0,1> }
  interior { ior 1.5 }
}
blob { threshold 0.5
  cylinder { <0,0,0>, <0,2,0>, 1.0, 1.0 }
  sphere { <0,2.5,0>, 0.8, -2.0 }
  sphere { <0,-0.52,0>, 0.8, -2.0 }
  texture { pigment { color rgb <0.8,0.50,0.01> } finish { diffuse 0.6 specular 0.6 roughness 0.1 subsurface { translucency <5,3,1>*0.5 } } }
  interior { ior 1.45 }
  rotate -y*45
}
