// Benchmark scene: a blob of N cylinder components (Declare=N=3000 on the command line;
// default 3000) scattered at random in a cube, solved with sturm: each ray meets only a
// few of them, which the blob's bounding hierarchy finds.
#version 3.7;
#ifndef (N) #declare N = 3000; #end
#declare S = seed(6);
camera { location <0, 0, -30> look_at 0 }
light_source { <-10, 10, -10> rgb 1 }
blob {
  #for (i, 1, N)
    #local P = <rand(S) - 0.5, rand(S) - 0.5, rand(S) - 0.5> * 20;
    cylinder { P, P + <rand(S) - 0.5, rand(S) - 0.5, rand(S) - 0.5> * 3, 0.3, 2 }
  #end
  sturm on
  pigment { rgb <0.7, 0.1, 0> }
}
