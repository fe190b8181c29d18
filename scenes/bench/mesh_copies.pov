// Benchmark scene: N copies (Declare=N=1200 on the command line; default 1200) of one
// 480-triangle mesh, each placed by a `matrix` in a colour of its own, as LeoCAD and
// LDraw exports write a model of many equal parts. The copies share the mesh's data and
// face tree (as POV-Ray shares a mesh between its copies): each is one primitive.
#version 3.7;
global_settings { assumed_gamma 1 }
#ifndef (N) #declare N = 1200; #end
#declare Columns = ceil(sqrt(N));
camera { location <Columns * 0.5, Columns * 0.9, -Columns * 0.4> look_at <Columns * 0.5, 0, Columns * 0.45> angle 60 }
light_source { <Columns, Columns * 2, -Columns> color rgb 1 }
plane { y, -0.2 pigment { color rgb 0.6 } }
// A ring of 40 sectors: outer and inner walls, top and bottom, 12 triangles per sector.
#declare Sectors = 40;
#declare Ring = mesh {
  #declare I = 0;
  #while (I < Sectors)
    #declare A0 = 2 * pi * I / Sectors;
    #declare A1 = 2 * pi * (I + 1) / Sectors;
    #declare O0 = <0.3 * cos(A0), 0, 0.3 * sin(A0)>;
    #declare O1 = <0.3 * cos(A1), 0, 0.3 * sin(A1)>;
    #declare N0 = <0.2 * cos(A0), 0, 0.2 * sin(A0)>;
    #declare N1 = <0.2 * cos(A1), 0, 0.2 * sin(A1)>;
    #declare H = 0.1 * y;
    triangle { O0, O1, O1 + H } triangle { O1 + H, O0 + H, O0 }
    triangle { N0, N1, N1 + H } triangle { N1 + H, N0 + H, N0 }
    triangle { O0 + H, O1 + H, N1 + H } triangle { N1 + H, N0 + H, O0 + H }
    triangle { O0, O1, N1 } triangle { N1, N0, O0 }
    // Ridges on the top, as studs and bevels add triangles to a part.
    triangle { O0 + H, N0 + H, (O0 + N1) / 2 + 1.5 * H }
    triangle { O1 + H, N1 + H, (O0 + N1) / 2 + 1.5 * H }
    triangle { O0 + H, O1 + H, (O0 + N1) / 2 + 1.5 * H }
    triangle { N0 + H, N1 + H, (O0 + N1) / 2 + 1.5 * H }
    #declare I = I + 1;
  #end
}
#declare S = seed(11);
#declare I = 0;
#while (I < N)
  #declare Turn = 2 * pi * rand(S);
  object { Ring
    pigment { color rgb <rand(S), rand(S), rand(S)> } finish { phong 0.3 }
    matrix < cos(Turn), 0, sin(Turn),  0, 1, 0,  -sin(Turn), 0, cos(Turn),
             mod(I, Columns) + 0.2 * rand(S), 0.1 * rand(S), div(I, Columns) + 0.2 * rand(S) >
  }
  #declare I = I + 1;
#end
