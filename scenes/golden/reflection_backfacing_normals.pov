// Angle-dependent reflection where a normal pattern tilts the normal away from the viewer:
// POV-Ray takes the signed cosine (ComputeReflectivity with -D.N of the perturbed normal),
// so fresnel clamps to reflection_max there, the variable fraction 1 - cos exceeds 1 (with
// and without falloff) and metallic's tint goes by the same angle; conserve_energy takes
// that reflectivity off what passes a glass slab, seen from in front and from inside
// (its back face). Plain-normal spheres beside them never face away.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -10> look_at <0, 1, 0> angle 60 }
light_source { <-20, 300, -40> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.9, 1>] [1 rgb <0.1, 0.2, 0.8>] } } }
// Floor patches: fresnel, variable with falloff, variable metallic.
box { <-9, -1, -3>, <-2.5, 0, 40>
      texture { pigment { rgb <0.2, 0.7, 0.3> } finish { ambient 0.2 diffuse 0 reflection { 0, 1 fresnel on } }
                normal { bumps 0.8 scale 2 } }
      interior { ior 1.3 } }
box { <-2.5, -1, -3>, <2.5, 0, 40>
      texture { pigment { rgb <0.7, 0.3, 0.2> } finish { ambient 0.2 diffuse 0.2 reflection { 0.05, 0.9 falloff 2 } }
                normal { wrinkles 0.9 scale 1.5 } } }
box { <2.5, -1, -3>, <9, 0, 40>
      texture { pigment { rgb <0.9, 0.7, 0.2> } finish { ambient 0.1 diffuse 0.2 reflection { 0.1, 1 metallic } }
                normal { dents 1.2 scale 1 } } }
// A glass slab with bumps and fresnel reflection in front of a checker wall.
box { <1, 1.2, 1>, <5.5, 4.5, 1.6>
      texture { pigment { rgbf <0.9, 0.95, 1, 0.9> }
                finish { ambient 0 diffuse 0 reflection { 0.02, 1 fresnel on } conserve_energy }
                normal { bumps 1.2 scale 0.4 } }
      interior { ior 1.5 } }
box { <0.5, 1, 6>, <8, 6, 6.5> pigment { checker rgb 0.9 rgb <0.1, 0.3, 0.6> scale 0.7 } finish { ambient 0.3 } }
// Plain normals: the same finishes on spheres.
sphere { <-4, 3.8, 1>, 0.6 texture { pigment { rgb <0.2, 0.7, 0.3> } finish { ambient 0.2 diffuse 0 reflection { 0, 1 fresnel on } } } interior { ior 1.3 } }
sphere { <-2.5, 2.5, 1>, 0.6 texture { pigment { rgb <0.7, 0.3, 0.2> } finish { ambient 0.2 diffuse 0.2 reflection { 0.05, 0.9 falloff 2 } } } }
sphere { <-1, 3.8, 1>, 0.6 texture { pigment { rgb <0.9, 0.7, 0.2> } finish { ambient 0.1 diffuse 0.2 reflection { 0.1, 1 metallic } } } }
