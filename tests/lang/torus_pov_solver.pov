// A torus's hits come from POV-Ray's own quartic solver (closed form unless sturm): on
// thin large tori it loses accuracy and roots, and POV-Ray's pixels follow those roots.
#version 3.7;
#declare N = <0, 0, 0>;
#macro Shoot(Obj, From, Dir)
  #local P = trace(Obj, From, Dir, N);
  #if (vlength(N) = 0)
    #debug "miss\n"
  #else
    #debug concat(str(vlength(P - From), 0, 9), "\n")
  #end
#end
#debug "BEGIN\n"
Shoot(torus { 1000, 1 }, <-2000, 0, 0>, x)
Shoot(torus { 1000, 1 sturm }, <-2000, 0, 0>, x)
Shoot(torus { 2, 0.5 }, <-10, 0, 0>, x)
Shoot(torus { 1, 1e-4 }, <1, 5, 0>, -y)
// The thin habitat ring of a public scene, edge-on, across its tube at several heights.
#declare Ring = torus { 70, 1.25 rotate 90 * z };
#declare I = -1.3;
#while (I <= 1.3)
  Shoot(Ring, <I, -200, 0.3>, y)
  Shoot(Ring, <I, 0.7, -200>, z)
  #declare I = I + 0.1;
#end
// Grazing a thin torus along its tube.
#declare I = 0;
#while (I < 8)
  Shoot(torus { 50, 0.5 }, <-100, 0.49 - I * 0.06, 50.2>, <1, 0, -0.001 * I>)
  #declare I = I + 1;
#end
#debug "END\n"
