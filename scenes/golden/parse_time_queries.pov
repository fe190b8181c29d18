// trace(), inside(), min_extent() and max_extent() while parsing, as scenes use them:
// pins stuck into a CSG rock along its normals where trace() meets it (a seeded random
// scatter, the hits' normals through a rotated and scaled union), coloured by inside()
// of a second object; a wire box around a turned union from its extents (POV-Ray's box
// of the turned box); a label centred with its extents.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -9> look_at <0, 0.6, 0> angle 50 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -3> color rgb 0.4 }
plane { y, -0.01 pigment { checker rgb <0.3, 0.5, 0.3> rgb <0.85, 0.85, 0.8> } }

#declare Rock = union {
  sphere { 0, 1 scale <1.6, 0.7, 1.1> }
  torus { 1.1, 0.3 rotate 20 * x translate 0.3 * y }
  difference {
    box { -0.6, 0.6 rotate <20, 35, 10> }
    sphere { <0.5, 0.5, -0.5>, 0.45 }
    translate <0.6, 0.5, 0.2>
  }
  rotate 15 * y scale <1.2, 1, 1>
}
object { Rock pigment { rgb <0.55, 0.45, 0.35> } }
#declare Zone = cylinder { <0.3, -5, 0>, <0.3, 5, 0>, 0.8 }
#declare R = seed(7);
#declare I = 0;
#while (I < 160)
  #declare Start = <-2.4 + 4.8 * rand(R), 4, -1.8 + 3.6 * rand(R)>;
  #declare N = <0, 0, 0>;
  #declare P = trace(Rock, Start, -y + 0.2 * x, N);
  #if (vlength(N) > 0)
    union {
      cylinder { P, P + 0.35 * N, 0.025 }
      sphere { P + 0.35 * N, 0.06 }
      pigment { #if (inside(Zone, P)) rgb <0.9, 0.2, 0.1> #else rgb <0.1, 0.3, 0.9> #end }
    }
  #end
  #declare I = I + 1;
#end

#declare Turned = union {
  box { <-0.5, 0, -0.3>, <0.5, 0.4, 0.3> }
  sphere { <0, 0.6, 0>, 0.3 }
  rotate <0, 40, 25> translate <-2.6, 0.4, 1.6>
}
object { Turned pigment { rgb <0.9, 0.8, 0.2> } }
#macro Wire(Lo, Hi, R)
  #local C = array[8];
  #for (K, 0, 7)
    #local C[K] = <select(mod(K, 2) - 0.5, Lo.x, Hi.x),
                   select(mod(div(K, 2), 2) - 0.5, Lo.y, Hi.y),
                   select(div(K, 4) - 0.5, Lo.z, Hi.z)>;
  #end
  union {
    #for (K, 0, 7)
      #for (B, 0, 2)
        #local J = bitwise_or(K, pow(2, B));
        #if (J != K) cylinder { C[K], C[J], R } #end
      #end
    #end
    pigment { rgb 0.1 }
  }
#end
Wire(min_extent(Turned), max_extent(Turned), 0.015)

#declare Label = text { internal 1 "povwall" 0.2, 0 scale 0.6 }
object { Label translate -(min_extent(Label) + max_extent(Label)) / 2
  rotate 30 * x translate <0.8, 1.9, 1.8> pigment { rgb <0.2, 0.7, 0.7> } }
